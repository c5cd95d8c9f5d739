#!/usr/bin/env bash
# kerf-dem calibrate_cut (the bond-strength factor fitted to one measured cut): bad input exits 2 naming the
# field; a small fit writes one directory per evaluation, the log, the summary and the fitted material, whose
# bond strengths are the base's times the reported factor; killed during its second evaluation and run
# again, it reuses the finished replicates and ends as the uninterrupted fit (log but its wall times,
# material file, summary results).
# Usage: dem_calibrate_cut_cli.sh <dir of built programs> <source dir>
source "$(dirname "$0")/lib/dem_common.sh" "$@"

scene="$src/data/scenes/dem_calibrate_cut.json"
expect_input_error "calibration.target_cutting_force_N = -1" run "$scene" --set calibration.target_cutting_force_N=-1 --out "$work/x"
# target_main_force_N, the old name (issue 55 item 5), is read until 0.3.0 with a warning, its error under its own name;
# both names at once are an error.
sed 's/"target_cutting_force_N"/"target_main_force_N"/' "$scene" >"$work/old_name.json"
expect_input_error "calibration.target_main_force_N = -1" run "$work/old_name.json" --set calibration.target_main_force_N=-1 \
  --out "$work/x"
expect_input_error "calibration.replicates = 1" run "$work/old_name.json" --set calibration.replicates=1 --out "$work/x"
grep -qF "warning: calibration.target_main_force_N is deprecated" "$work/err" || fail "no warning for the old name"
expect_input_error "calibration.target_main_force_N = 3" run "$scene" --set calibration.target_main_force_N=3 --out "$work/x"
expect_input_error "calibration.replicates = 1" run "$scene" --set calibration.replicates=1 --out "$work/x"
expect_input_error "--replicates = 2" run "$scene" --replicates 2 --out "$work/x"
expect_input_error "--checkpoint-every" run "$scene" --checkpoint-every 5 --out "$work/x"
[ ! -e "$work/x/summary.json" ] || fail "a rejected scene wrote output"

small=(--set specimen.width_mm=0.4 --set specimen.height_mm=0.25 --set specimen.growth_steps=2000
       --set specimen.relax_steps=500 --set cut.depth_of_cut_mm=0.05 --set cut.length_mm=0.04
       --set cut.speed_m_per_s=2 --set calibration.replicates=2 --set calibration.max_evaluations=3
       --set calibration.target_cutting_force_N=3 --set calibration.tolerance_percent=1 --threads 1)
"$bin" run "$scene" "${small[@]}" --out "$work/full" >"$work/full.out" 2>&1
rc=$?
[ $rc -eq 0 ] || [ $rc -eq 3 ] || fail "calibrate_cut exit $rc: $(cat "$work/full.out")"
for f in summary.json calibration_log.csv soda_lime_glass_fj_cut.json evaluation_1/replicates/items/condition_1_seed_2/forces.csv evaluation_1/replicates/study.json; do
  [ -s "$work/full/$f" ] || fail "missing $f"
done
rows=$(($(wc -l < "$work/full/calibration_log.csv") - 1))
[ $rows -ge 2 ] || fail "expected at least two evaluations, got $rows"
# Evaluation 1 runs the base material (factor 1); the fitted file's strengths are the base's times the factor.
awk -F, 'NR == 2 && $2 != 1 { exit 1 }' "$work/full/calibration_log.csv" || fail "evaluation 1 is not at factor 1"
factor=$(grep -o '"strength_factor": [-0-9.e+]*' "$work/full/summary.json" | tail -1 | awk '{print $2}')
sigma=$(grep -A2 '"tensile_strength_MPa": {' "$work/full/soda_lime_glass_fj_cut.json" | grep -o '"value": [-0-9.e+]*' | awk '{print $2}')
base=$(awk -F, 'NR == 2 { print $3 }' "$work/full/calibration_log.csv")  # evaluation 1: the base material
awk -v s="$sigma" -v b="$base" -v f="$factor" 'BEGIN { exit !(s > 0 && (s - b * f) ^ 2 < (1e-9 * s) ^ 2) }' ||
  fail "fitted sigma_c $sigma is not the base's $base x $factor"

# Killed while its second evaluation runs, then the same command again.
"$bin" run "$scene" "${small[@]}" --out "$work/kill" >/dev/null 2>&1 &
pid=$!
for _ in $(seq 3000); do [ -e "$work/kill/evaluation_2" ] && break; sleep 0.01; done
kill -9 $pid 2>/dev/null || fail "the fit ended before it could be killed"
wait $pid 2>/dev/null
[ ! -e "$work/kill/summary.json" ] || fail "the killed fit had already finished"
"$bin" run "$scene" "${small[@]}" --out "$work/kill" >"$work/kill.out" 2>&1
grep -q " reused in " "$work/kill.out" || fail "the rerun reused no finished replicate: $(cat "$work/kill.out")"
cmp -s <(cut -d, -f1-9 "$work/full/calibration_log.csv") <(cut -d, -f1-9 "$work/kill/calibration_log.csv") ||
  fail "rerun calibration_log.csv differs: $(diff "$work/full/calibration_log.csv" "$work/kill/calibration_log.csv")"
cmp -s "$work/full/soda_lime_glass_fj_cut.json" "$work/kill/soda_lime_glass_fj_cut.json" || fail "rerun material differs"
results() { sed -n '/^  "results": {/,/^  }/p' "$1/summary.json"; }
[ -n "$(results "$work/full")" ] || fail "no results in summary.json"
cmp -s <(results "$work/full") <(results "$work/kill") || fail "rerun summary results differ"
echo "dem_calibrate_cut_cli: ok"
