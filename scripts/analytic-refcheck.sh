#!/usr/bin/env bash
# Proves an analytic refactor changed no result: runs the same reference cases with two builds and compares
# them byte for byte (as scripts/dem-refcheck.sh does for the DEM; the logs but for the output directory's name).
#
#   bash scripts/analytic-refcheck.sh OLD_BIN_DIR NEW_BIN_DIR OUT_DIR
#
# BIN_DIR holds kerf-forces (e.g. build/tools of the commit before the change); BIN_DIR/../validation/
# run_validation, when present, regenerates the K9 trepanning validation. BIN_DIR/../python, when it holds the
# module, runs Python's predict and sweep (numbers compared with ==, NaN equal to NaN). Cases: every bundled
# kerf-forces scene (data/scenes/*.json without a "kind"; validation/k9_trepanning/scene.json) predicted with
# its text report and CSV, and its regime; the 100,000-point sweep of docs/performance.md; a turning sweep with
# refused points; the K9 trepanning sweep, compare --fit and validation report. About a minute on 2 cores.
# Exit 0 when everything is identical.
set -uo pipefail
src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
old=$1 new=$2 out=$3
k9="$src/validation/k9_trepanning/scene.json"
forces_scenes() {
  for f in "$src"/data/scenes/*.json; do grep -q '"kind"' "$f" || echo "$f"; done
  echo "$k9"
}
run_cases() {  # BIN_DIR DIR
  local bin=$1/kerf-forces dir=$2
  mkdir -p "$dir"
  for f in $(forces_scenes); do
    local name; name=$(basename "$f" .json)
    (cd "$src" && "$bin" predict "$f" --csv "$dir/$name.csv" >"$dir/$name.txt" 2>&1; echo "exit $?" >>"$dir/$name.txt")
    (cd "$src" && "$bin" regime "$f" >"$dir/$name.regime.txt" 2>&1; echo "exit $?" >>"$dir/$name.regime.txt")
  done
  "$bin" sweep "$src/data/scenes/psic_orthogonal.json" --vary cut.uncut_chip_thickness_um=0.001:10:1000:log \
    --vary tool.edge_radius_um=0:1:100 --csv "$dir/sweep100k.csv" --threads 2 >"$dir/sweep100k.log" 2>&1
  "$bin" sweep "$src/data/scenes/psic_orthogonal.json" --vary tool.rake_deg=-95,-30,0,30 \
    --vary cut.uncut_chip_thickness_um=0.05:1.5:6 --csv "$dir/refused.csv" --threads 2 >"$dir/refused.log" 2>&1
  "$bin" sweep "$src/data/scenes/a2024_planing.json" --vary cut.speed_m_per_min=50:400:8 --vary tool.rake_deg=0,10 \
    --csv "$dir/a2024.csv" --plot "$dir/a2024.png" --threads 2 >"$dir/a2024.log" 2>&1
  "$bin" sweep "$k9" --vary cut.feed_rate_um_per_s=10:20:11 --vary cut.spindle_speed_rpm=90.5,181 \
    --csv "$dir/k9sweep.csv" >"$dir/k9sweep.log" 2>&1
  "$bin" compare "$k9" --experiments "$src/data/experiments/k9_trepanning.csv" --map cut.feed_rate_um_per_s=feed_rate_um_s \
    --map axial_force_N=axial_force_test_N --map torque_N_m=torque_test_Nm --fit --out "$dir/k9compare" >"$dir/k9compare.log" 2>&1
  if [ -x "$1/../validation/run_validation" ]; then
    (cd "$src" && "$1/../validation/run_validation" k9_trepanning "$dir/validation" >"$dir/validation.log" 2>&1)
  fi
  if [ -f "$(ls "$1"/../python/kerf*.so 2>/dev/null | head -1)" ]; then
    (cd "$src" && PYTHONPATH="$1/../python" OMP_NUM_THREADS=2 /usr/bin/python3 - "$dir/python.pickle" <<'PY')
import pickle, sys
import kerf
scene = "data/scenes/psic_orthogonal.json"
out = {
    "predict": kerf.predict(scene, tool__edge_radius_um=0.2),
    "predict_k9": kerf.predict("validation/k9_trepanning/scene.json"),
    "sweep": kerf.sweep(scene, vary={"cut.uncut_chip_thickness_um": [0.01 * i for i in range(1, 101)],
                                     "tool.edge_radius_um": [0, 0.1, 0.5], "tool.rake_deg": [-95, 0, 10]}),
    "sweep_k9": kerf.sweep("validation/k9_trepanning/scene.json", vary={"cut.feed_rate_um_per_s": [10, 15.5, 20]}),
}
pickle.dump({k: {c: (v.tolist() if hasattr(v, "tolist") else v) for c, v in d.items()} for k, d in out.items()},
            open(sys.argv[1], "wb"))
PY
  fi
}
run_cases "$old" "$out/old"
run_cases "$new" "$out/new"
rc=0
for f in $(cd "$out/old" && find . -type f \( -name '*.csv' -o -name '*.txt' -o -name '*.md' -o -name '*.json' -o -name '*.log' -o -name '*.png' \) | sort); do
  # The output directory's own name (in the logs) is the one difference allowed.
  if cmp -s <(sed "s|$out/old|OUT|g" "$out/old/$f") <(sed "s|$out/new|OUT|g" "$out/new/$f" 2>/dev/null); then echo "same      ${f#./}"; else echo "DIFFERENT ${f#./}"; rc=1; fi
done
if [ -f "$out/old/python.pickle" ]; then
  /usr/bin/python3 - "$out/old/python.pickle" "$out/new/python.pickle" <<'PY' || rc=1
import math, pickle, sys
a, b = (pickle.load(open(p, "rb")) for p in sys.argv[1:3])
def same(x, y):
    if isinstance(x, float) and isinstance(y, float):
        return x == y or (math.isnan(x) and math.isnan(y))
    if isinstance(x, dict) and isinstance(y, dict):
        return x.keys() == y.keys() and all(same(x[k], y[k]) for k in x)
    if isinstance(x, (list, tuple)) and isinstance(y, (list, tuple)):
        return len(x) == len(y) and all(same(u, v) for u, v in zip(x, y))
    return type(x) == type(y) and x == y
for key in a:
    print(("same      " if same(a[key], b[key]) else "DIFFERENT ") + "python " + key)
sys.exit(0 if all(same(a[k], b[k]) for k in a) else 1)
PY
fi
exit $rc
