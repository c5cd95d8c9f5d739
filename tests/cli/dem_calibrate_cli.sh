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
echo "dem_calibrate_cli: ok"
