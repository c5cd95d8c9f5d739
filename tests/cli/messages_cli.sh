#!/usr/bin/env bash
# Issue 40 item 8: the messages of a new user's mistakes name what went wrong in the user's own terms. Each is
# one 'error:' line and exit 2: a number written with its unit; a relation between two keys blamed on the key
# the user set; a misspelled required section; a scene given to the other program; a misspelled material
# suggesting only the materials that have the group the scene needs. Nothing here runs a simulation.
source "$(dirname "$0")/lib/forces_common.sh" "$@"
dem="$1/kerf-dem"
export KERF_DATA_DIR="$src/data"
orthogonal="$src/data/scenes/psic_orthogonal.json"

# A unit after the number: not a number; the unit is in the key's name.
expect 2 "tool.edge_radius_um = 0.2um: expected a non-negative value in um ('0.2um' is not a number; the unit is in the key name, um: write 0.2)" \
  -- predict "$orthogonal" --set tool.edge_radius_um=0.2um
expect 2 "is not a number; the unit is in the key name" -- predict "$orthogonal" --set "cut.width_mm=1 mm"
# A misspelled required section: the section the scene has instead is named.
python3 -c "import json,sys; d=json.load(open(sys.argv[1])); d['tools']=d.pop('tool'); json.dump(d, open(sys.argv[2],'w'))" \
  "$orthogonal" "$tmp/tools.json"
expect 2 "tool = (missing): expected a value for this required key (the scene has 'tools': did you mean 'tool'?)" \
  -- predict "$tmp/tools.json"
# A kerf-dem scene given to kerf-forces: its kind and its program, before any of its keys is read.
expect 2 "this is a kerf-dem scene (kind: cut); run it with kerf-dem run" -- predict "$src/data/scenes/dem_cut.json"
expect 2 "this is a kerf-dem scene (kind: tension)" -- sweep "$src/data/scenes/dem_tension.json" \
  --vary cut.width_mm=1,2 --csv "$tmp/s.csv"

# expect_dem STATUS PATTERN -- ARGS...: as expect, for kerf-dem.
expect_dem() { expect_of kerf-dem "$dem" "$@"; }
cut="$src/data/scenes/dem_cut.json"
# The reverse: an analytic scene given to kerf-dem.
expect_dem 2 "this is a kerf-forces scene (analytic models, no kind); run it with kerf-forces predict" \
  -- run "$orthogonal" --out "$tmp/o"
# radius_min_um above radius_max_um: the key the user set is the one named, whichever it is.
max_um=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['specimen']['radius_max_um'])" "$cut")
min_um=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['specimen']['radius_min_um'])" "$cut")
expect_dem 2 "specimen.radius_min_um = 20: expected a value <= radius_max_um = $max_um um" \
  -- run "$cut" --set specimen.radius_min_um=20 --out "$tmp/r"
expect_dem 2 "specimen.radius_max_um = 1: expected a value >= radius_min_um = $min_um um" \
  -- run "$cut" --set specimen.radius_max_um=1 --out "$tmp/r"
# A misspelled material in a DEM scene: the suggestion has a "dem" group, and no material without one is listed.
expect_dem 2 "material.base = soda_lime_glas: expected one of" -- run "$cut" --set material.base=soda_lime_glas --out "$tmp/m"
grep -qF "(did you mean 'soda_lime_glass_fj" "$tmp/err" || { echo "FAIL: no DEM material suggested: $(cat "$tmp/err")"; failures=$((failures + 1)); }
for analytic_only in psic aisi_1045 "soda_lime_glass'"; do
  if grep -qF "'$analytic_only" "$tmp/err"; then
    echo "FAIL: a material without a dem group is offered ($analytic_only): $(cat "$tmp/err")"; failures=$((failures + 1))
  fi
done
# kerf-forces still offers every material.
expect 2 "(did you mean 'soda_lime_glass'?)" -- predict "$orthogonal" --set material=soda_lime_glas

[ "$failures" -eq 0 ] && echo "all message checks passed"
exit "$failures"
