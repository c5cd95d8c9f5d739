#!/usr/bin/env bash
# kerf-forces results: the column table in docs/scenes.md ("Output columns") and the Python module of the columns
# (python/kerf/prediction_keys.py) are the ones generated from the result tables the prediction's row and report are
# written from (regenerate: build/tools/kerf-forces results, pasted between the markers; build/tools/kerf-forces
# results --python > python/kerf/prediction_keys.py); the CSV's header holds the table's columns in its order.
# Usage: forces_results_cli.sh <dir of built programs> <source dir>
set -uo pipefail
bin="$1/kerf-forces"; src="$2"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
source "$(dirname "$0")/lib/generated.sh"

"$bin" results >"$work/results.md" || fail "kerf-forces results failed"
generated_block "$work/results.md" "$src/docs/scenes.md" "kerf-forces results"
"$bin" results --python >"$work/prediction_keys.py" || fail "kerf-forces results --python failed"
generated_file "$work/prediction_keys.py" "$src/python/kerf/prediction_keys.py"
# A prediction's CSV header: the tables' columns (the shared ones, the edge's of a liu_li scene; their order:
# tests/analytic/predict_test.cpp).
(cd "$src" && "$bin" predict data/scenes/psic_orthogonal.json --csv "$work/p.csv" >/dev/null) || fail "predict failed"
header=$(head -1 "$work/p.csv" | tr ',' '\n')
for key in force_model cutting_force_N cutting_force_N_per_mm shear_angle_deg temperature_K warnings \
  lower_limit_deg ploughing_attack_angle_deg; do
  grep -qx "$key" <<<"$header" || fail "the CSV has no column $key"
  grep -q "^| \`$key\` |" "$work/results.md" || fail "kerf-forces results: no row for $key"
done
echo "forces results cli: ok"
