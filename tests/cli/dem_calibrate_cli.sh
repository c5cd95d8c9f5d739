#!/usr/bin/env bash
# kerf-dem calibrate: a bad calibration.method exits 2; a calibration killed after its first evaluation and
# resumed ends as one never interrupted (material file, summary results, evaluation log but its wall times).
# Tiny specimen, so the whole script runs in seconds.
# Usage: dem_calibrate_cli.sh <dir of built programs> <source dir>
source "$(dirname "$0")/lib/dem_common.sh" "$@"

scene="$src/data/scenes/dem_calibrate.json"
expect_input_error "calibration.method = newton: expected one of 'hybrid', 'secant'" run "$scene" \
  --set calibration.method=newton --out "$work/x"
expect_input_error "--checkpoint-every" run "$src/data/scenes/dem_specimen.json" --checkpoint-every 1 --out "$work/x"

tiny=(--set specimen.width_mm=0.16 --set specimen.height_mm=0.32 --set specimen.growth_steps=2000
      --set specimen.relax_steps=500 --set loading.speed_m_per_s=0.2 --set calibration.max_evaluations=6
      --set calibration.tolerance_percent=15 --set calibration.material_name=tiny_fj --threads 1)
"$bin" run "$scene" "${tiny[@]}" --out "$work/full" >"$work/full.out" 2>&1 || fail "calibration: $(cat "$work/full.out")"
[ "$(wc -l < "$work/full/calibration_log.csv")" -ge 3 ] || fail "expected at least two evaluations (to kill between)"
expect_kill_resume_equal "$work/full" "$work/kill" "tiny_fj.json" run "$scene" "${tiny[@]}" --checkpoint-every 1
# The log, less its wall_time_s column (the evaluations after the resume ran again).
cmp -s <(cut -d, -f1-10 "$work/full/calibration_log.csv") <(cut -d, -f1-10 "$work/kill/calibration_log.csv") ||
  fail "resumed calibration_log.csv differs: $(diff "$work/full/calibration_log.csv" "$work/kill/calibration_log.csv")"
results() { sed -n '/^  "results": {/,/^  }/p' "$1/summary.json"; }
[ -n "$(results "$work/full")" ] || fail "no results in summary.json"
cmp -s <(results "$work/full") <(results "$work/kill") || fail "resumed summary results differ"
# A saved specimen is one packing: more is refused, naming the key, before any evaluation.
"$bin" run "$src/data/scenes/dem_specimen.json" "${tiny[@]:0:8}" --threads 1 --out "$work/spec" >/dev/null 2>&1 ||
  fail "tiny specimen for specimen.file"
python3 -c 'import json, sys; s = json.load(open(sys.argv[1])); s["specimen"] = {"file": sys.argv[2]}; json.dump(s, open(sys.argv[3], "w"))' \
  "$scene" "$work/spec/specimen.json" "$work/from_file.json" || fail "scene with specimen.file"
expect_input_error "calibration.packings = 2: expected 1 with specimen.file" run "$work/from_file.json" \
  --set calibration.packings=2 --out "$work/x"
# The fifth target (issue 37): bad input named before any genesis; a tiny five-target calibration killed and
# resumed ends as one never interrupted, its log with the toughness's columns.
tscene="$src/data/scenes/dem_calibrate_toughness.json"
python3 -c 'import json, sys; s = json.load(open(sys.argv[1])); del s["calibration"]["toughness"]; json.dump(s, open(sys.argv[2], "w"))' \
  "$tscene" "$work/no_beam.json" || fail "scene without a toughness test"
expect_input_error "calibration.targets.fracture_toughness_MPa_sqrt_m = 0.77: expected a calibration.toughness test" \
  run "$work/no_beam.json" --out "$work/x"
expect_input_error "material.fracture_energy_J_per_m2 = 0: expected a bond_model softening_flat_joint with a fracture" \
  run "$tscene" --set material.fracture_energy_J_per_m2=0 --out "$work/x"
expect_input_error "calibration.toughness.notch_depth_mm = 0.6" run "$tscene" --set calibration.toughness.notch_depth_mm=0.6 \
  --out "$work/x"
expect_input_error "calibration.toughness.quasi_static_check = true: expected false" run "$tscene" \
  --set calibration.toughness.quasi_static_check=true --out "$work/x"
five=(--set specimen.width_mm=0.16 --set specimen.height_mm=0.32 --set specimen.growth_steps=2000
      --set specimen.relax_steps=500 --set specimen.radius_min_um=7.5 --set specimen.radius_max_um=10
      --set loading.speed_m_per_s=0.2 --set calibration.packings=1 --set calibration.max_evaluations=3
      --set calibration.tolerance_percent=15 --set calibration.toughness_tolerance_percent=50
      --set calibration.toughness.beam_depth_mm=0.2 --set calibration.toughness.beam_length_mm=0.86
      --set calibration.toughness.notch_depth_mm=0.08 --set calibration.toughness.roller_radius_mm=0.03
      --set calibration.toughness.speed_m_per_s=0.1 --set calibration.material_name=tiny_sfj --threads 1)
"$bin" run "$tscene" "${five[@]}" --out "$work/five" >"$work/five.out" 2>&1
[ -s "$work/five/calibration_log.csv" ] || fail "five-target calibration: $(cat "$work/five.out")"
head -1 "$work/five/calibration_log.csv" | grep -q "fracture_energy_J_per_m2,macro_fracture_toughness_MPa_sqrt_m" ||
  fail "the log lacks the toughness's columns: $(head -1 "$work/five/calibration_log.csv")"
grep -q "K_IC" "$work/five.out" || fail "no K_IC in the evaluation lines: $(cat "$work/five.out")"
# The start (the steady cut's glass with G_f = 7 J/m^2 on smaller disks) is far too strong: a second evaluation.
[ "$(wc -l < "$work/five/calibration_log.csv")" -ge 3 ] || fail "expected at least two evaluations (to kill between)"
expect_kill_resume_equal "$work/five" "$work/five_kill" "tiny_sfj.json" run "$tscene" "${five[@]}" --checkpoint-every 1
cmp -s <(cut -d, -f1-10,12- "$work/five/calibration_log.csv") <(cut -d, -f1-10,12- "$work/five_kill/calibration_log.csv") ||
  fail "resumed five-target log differs: $(diff "$work/five/calibration_log.csv" "$work/five_kill/calibration_log.csv")"
echo "dem_calibrate_cli: ok"
