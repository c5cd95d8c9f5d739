#!/usr/bin/env bash
# Proves a DEM refactor changed no result: runs the same reference cases with two builds and compares them
# (CSV outputs byte for byte; summary.json and fitted materials as JSON without wall times and provenance (binary
# path, commit, date), an old flat-joint material's friction_coefficient also its residual_friction_coefficient (see
# below); calibration logs without wall times).
#
#   bash scripts/dem-refcheck.sh OLD_BIN_DIR NEW_BIN_DIR OUT_DIR [--skip-compression]
#
# BIN_DIR holds kerf-dem (e.g. build/tools of a worktree of the commit before the change). Cases: the first
# 0.04 mm of the Yang et al. 2018 cut (regular 0.1 mm, trapezoidal-grooved 0.2 mm), the first 0.2 mm of the bundled
# steady-state cut (active window), the first 0.8 mm of the same cut without a window on a 1.5 mm workpiece
# (fragments fly off undamped: the neighbour search's strays), the bundled tension and
# compression scenes (2 threads), the tiny calibration of tests/cli/dem_calibrate_cli.sh. About 5 min on
# 2 cores, most of it the compression test and its quasi-static check. Exit 0 when everything is identical.
set -uo pipefail
src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
old=$1 new=$2 out=$3 skip=${4:-}
run_cases() {  # BIN_DIR DIR
  local bin=$1/kerf-dem dir=$2 v=$src/validation/soda_lime_cutting/scene.json
  mkdir -p "$dir"
  "$bin" run "$v" --set cut.length_mm=0.04 --out "$dir/cut004" --threads 2 >"$dir/cut004.log" 2>&1
  "$bin" run "$v" --set cut.length_mm=0.04 --set grooves.shape=trapezoidal --set cut.depth_of_cut_mm=0.2 \
    --out "$dir/cutg004" --threads 2 >"$dir/cutg004.log" 2>&1
  # The first 0.2 mm of the bundled steady-state cut (12 mm workpiece, active window, undamped glass).
  "$bin" run "$src/data/scenes/dem_cut_steady.json" --set cut.length_mm=0.2 --set output.frame_every_samples=0 \
    --out "$dir/steady02" --threads 2 >"$dir/steady02.log" 2>&1
  "$bin" run "$src/data/scenes/dem_cut_steady.json" --set cut.length_mm=0.8 --set specimen.width_mm=1.5 \
    --set active_window.enabled=false --set output.frame_every_samples=0 \
    --out "$dir/whole08" --threads 2 >"$dir/whole08.log" 2>&1
  "$bin" run "$src/data/scenes/dem_tension.json" --out "$dir/tension" --threads 2 >"$dir/tension.log" 2>&1
  [ "$skip" = --skip-compression ] ||
    "$bin" run "$src/data/scenes/dem_compression.json" --out "$dir/compression" --threads 2 >"$dir/compression.log" 2>&1
  "$bin" run "$src/data/scenes/dem_calibrate.json" --set specimen.width_mm=0.16 --set specimen.height_mm=0.32 \
    --set specimen.growth_steps=2000 --set specimen.relax_steps=500 --set loading.speed_m_per_s=0.2 \
    --set calibration.max_evaluations=6 --set calibration.tolerance_percent=15 \
    --set calibration.material_name=tiny_fj --threads 1 --out "$dir/calib" >"$dir/calib.log" 2>&1
}
run_cases "$old" "$out/old"
run_cases "$new" "$out/new"
rc=0
for f in cut004/forces.csv cut004/cracks.csv cutg004/forces.csv cutg004/cracks.csv steady02/forces.csv \
  steady02/cracks.csv whole08/forces.csv whole08/cracks.csv tension/curve.csv \
  tension/cracks.csv compression/curve.csv compression/cracks.csv; do
  [ -f "$out/old/$f" ] || continue
  if cmp -s "$out/old/$f" "$out/new/$f"; then echo "same      $f"; else echo "DIFFERENT $f"; rc=1; fi
done
if cmp -s <(cut -d, -f1-10 "$out/old/calib/calibration_log.csv") <(cut -d, -f1-10 "$out/new/calib/calibration_log.csv"); then
  echo "same      calib/calibration_log.csv (but its wall_time_s column)"
else
  echo "DIFFERENT calib/calibration_log.csv"; rc=1
fi
# A material written before issue 39 has one friction_coefficient, which set the linear contact's friction and the
# flat joint's residual friction alike; since then the flat joint has its own key residual_friction_coefficient. The
# material objects (summary.json, the fitted material file) are compared as JSON with an old flat-joint material's
# friction_coefficient given to that key too, so that the new key must hold exactly the value the one key set.
for f in cut004/summary.json cutg004/summary.json steady02/summary.json whole08/summary.json tension/summary.json \
  compression/summary.json calib/summary.json calib/tiny_fj.json; do
  [ -f "$out/old/$f" ] || continue
  python3 - "$out/old/$f" "$out/new/$f" "$f" <<'PY' || rc=1
import json, sys
def strip(o):
    if isinstance(o, dict):
        o = dict(o)
        if "friction_coefficient" in o and "n_elements" in o and "residual_friction_coefficient" not in o:
            o["residual_friction_coefficient"] = o["friction_coefficient"]  # an old flat-joint material
        return {k: strip(v) for k, v in o.items()
                if not (k.startswith("wall_time") or k in ("particle_steps_per_s", "genesis_wall_time_s", "provenance"))}
    return [strip(v) for v in o] if isinstance(o, list) else o
a, b = (strip(json.load(open(p))) for p in sys.argv[1:3])
print(("same      " if a == b else "DIFFERENT ") + sys.argv[3] + " (as JSON, but wall times and provenance)")
sys.exit(0 if a == b else 1)
PY
done
exit $rc
