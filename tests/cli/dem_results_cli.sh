#!/usr/bin/env bash
# kerf-dem results: the result tables in docs/dem-keys.md and the Python module of their keys
# (python/kerf/result_keys.py) are the ones generated from the result tables (regenerate: build/tools/kerf-dem results,
# pasted between the markers; build/tools/kerf-dem results --python > python/kerf/result_keys.py); each key with a unit
# ends in its unit's suffix.
# Usage: dem_results_cli.sh <dir of built programs> <source dir>
source "$(dirname "$0")/lib/dem_common.sh" "$@"
source "$(dirname "$0")/lib/generated.sh"

"$bin" results >"$work/results.md" || fail "kerf-dem results failed"
generated_block "$work/results.md" "$src/docs/dem-keys.md" "kerf-dem results"
"$bin" results --python >"$work/result_keys.py" || fail "kerf-dem results --python failed"
generated_file "$work/result_keys.py" "$src/python/kerf/result_keys.py"
for key in subsurface_damage_depth_steady_um steady_from_travel_mm edge_zone_cutting_force_N_per_mm damage_depth_limit_um; do
  grep -q "^| \`$key\` |" "$work/results.md" || fail "kerf-dem results: no row for $key"
done
# A key's unit suffix is its unit's ("um" -> _um, "N/mm" -> _N_per_mm, "%" -> _percent, "MPa sqrt(m)" -> _MPa_sqrt_m):
# the rows with a unit.
awk -F' [|] ' '/^[|] `[a-z]/ && $2 != "-" && $2 != "" {
  n = split($1, keys, "`, `"); suffix = "_" $2; gsub("/", "_per_", suffix); gsub("%", "percent", suffix); gsub(/[ (]/, "_", suffix); gsub(/\)/, "", suffix)
  for (i = 1; i <= n; i++) { k = keys[i]; gsub(/[|` ]/, "", k); if (k !~ suffix "$") print k " (" $2 ")" }
}' "$work/results.md" >"$work/bad_suffix"
[ ! -s "$work/bad_suffix" ] || fail "result keys without their unit's suffix: $(cat "$work/bad_suffix")"
echo "dem results cli: ok"
