#!/usr/bin/env bash
# Categorical sweeps (issue 55 item 3): --vary over models and materials, crossed with a numeric key, gives the
# rows the separate predictions give (every column of each, the union's other columns empty), keeps each varied
# key as its own column (material_varied beside the prediction's material), and a figure needs a numeric first key.
# Usage: forces_categorical_sweep.sh <dir of built programs> <source dir>
set -uo pipefail
bin="$1/kerf-forces"; src="$2"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
scene="$src/data/scenes/soda_lime_transition.json"

"$bin" sweep "$scene" --vary cut.uncut_chip_thickness_um=0.02,5 --vary models.force=merchant,liu_li,transition \
  --vary material=soda_lime_glass,k9_glass --set tool.edge_radius_um=0.5 --csv "$work/sweep.csv" 2>"$work/err" ||
  fail "categorical sweep failed: $(cat "$work/err")"
for h in 0.02 5; do
  for model in merchant liu_li transition; do
    for material in soda_lime_glass k9_glass; do
      "$bin" predict "$scene" --set cut.uncut_chip_thickness_um=$h --set models.force=$model --set material=$material \
        --set tool.edge_radius_um=0.5 --csv "$work/$h-$model-$material.csv" >/dev/null 2>&1 || fail "predict $h $model $material"
    done
  done
done
python3 - "$work" <<'PY' || fail "the sweep's rows are not the separate predictions'"
import csv, sys
work = sys.argv[1]
rows = list(csv.DictReader(open(f"{work}/sweep.csv")))
assert len(rows) == 12, len(rows)
header = next(csv.reader(open(f"{work}/sweep.csv")))
assert header[:3] == ["cut.uncut_chip_thickness_um", "models.force", "material_varied"], header[:3]
for r in rows:
    one = next(csv.DictReader(open(f"{work}/{r['cut.uncut_chip_thickness_um']}-{r['models.force']}-{r['material_varied']}.csv")))
    for k, v in one.items():
        assert r[k] == v, (r["models.force"], r["material_varied"], k, r[k], v)
    for k in set(r) - set(one) - {"cut.uncut_chip_thickness_um", "models.force", "material_varied", "error"}:
        assert r[k] == "", (k, r[k])          # a column of another model: empty here
    assert r["material"] == r["material_varied"] and r["force_model"] == r["models.force"]
PY
"$bin" sweep "$scene" --vary models.force=merchant,liu_li --vary cut.uncut_chip_thickness_um=1,2 --csv "$work/x.csv" \
  --plot "$work/x.png" 2>"$work/err"; rc=$?
[ $rc -eq 2 ] && grep -q "numeric first --vary key" "$work/err" || fail "a categorical first key must refuse --plot (exit $rc)"
echo "PASS: categorical sweeps"
