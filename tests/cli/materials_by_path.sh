#!/usr/bin/env bash
# Materials (issue 23): unknown keys in every group are errors with a did-you-mean; a material by its path
# (kerf-forces and kerf-dem's material.base); KERF_MATERIAL_PATH adds to the bundled library.
set -u
forces="$1/kerf-forces"; dem="$1/kerf-dem"; src="$2"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
scene="$src/data/scenes/psic_orthogonal.json"

# A typo in the elastic and brittle groups: exit 2, naming the key and the near miss.
python3 - "$src/data/materials/psic.json" "$tmp" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
json.dump(m, open(sys.argv[2] + "/my_sic.json", "w"))
bad = json.loads(json.dumps(m)); bad["elastic"]["poisson_ratio"] = bad["elastic"].pop("poissons_ratio")
json.dump(bad, open(sys.argv[2] + "/typo_elastic.json", "w"))
bad = json.loads(json.dumps(m)); bad["brittle"]["foo"] = 1
json.dump(bad, open(sys.argv[2] + "/typo_brittle.json", "w"))
PY
"$forces" predict "$scene" --set material="$tmp/typo_elastic.json" >/dev/null 2>"$tmp/err"
[ $? -eq 2 ] || fail "an unknown elastic key must exit 2"
grep -q "material.elastic.poisson_ratio = .*did you mean 'poissons_ratio'" "$tmp/err" || { cat "$tmp/err"; fail "elastic typo"; }
"$forces" predict "$scene" --set material="$tmp/typo_brittle.json" >/dev/null 2>"$tmp/err"
[ $? -eq 2 ] || fail "an unknown brittle key must exit 2"
grep -q "material.brittle.foo = 1: expected a key of the brittle group" "$tmp/err" || { cat "$tmp/err"; fail "brittle key"; }

# A material by path predicts what the library's copy predicts.
"$forces" predict "$scene" --csv "$tmp/a.csv" >/dev/null || fail "library material"
"$forces" predict "$scene" --set material="$tmp/my_sic.json" --csv "$tmp/b.csv" >/dev/null || fail "material by path"
[ "$(cut -d, -f5- "$tmp/a.csv")" = "$(cut -d, -f5- "$tmp/b.csv")" ] || fail "the material by path predicts differently"
"$forces" predict "$scene" --set material="$tmp/none.json" >/dev/null 2>"$tmp/err"; [ $? -eq 2 ] || fail "missing file"
grep -q "none.json: expected a readable material file" "$tmp/err" || { cat "$tmp/err"; fail "missing file message"; }

# KERF_MATERIAL_PATH adds: its material and the bundled ones are both found.
mkdir "$tmp/lib"; cp "$src/data/materials/psic.json" "$tmp/lib/glass_of_mine.json"
KERF_MATERIAL_PATH="$tmp/lib" "$forces" materials >"$tmp/m" || fail "materials with a search path"
grep -q "^glass_of_mine" "$tmp/m" && grep -q "^soda_lime_glass_fj" "$tmp/m" || { cat "$tmp/m"; fail "search path"; }
KERF_MATERIAL_PATH="$tmp/lib" "$forces" predict "$scene" --set material=glass_of_mine >/dev/null || fail "by search path"

# kerf-dem: material.base by path.
cp "$src/data/materials/soda_lime_glass_fj.json" "$tmp/glass.json"
"$dem" run "$src/data/scenes/dem_specimen.json" --set material.base="$tmp/glass.json" --set specimen.width_mm=0.3 \
  --set specimen.height_mm=0.2 --set specimen.radius_min_um=10 --set specimen.radius_max_um=13 \
  --set specimen.growth_steps=200 --set specimen.relax_steps=100 --threads 1 \
  --out "$tmp/dem" >/dev/null 2>"$tmp/err" || { cat "$tmp/err"; fail "kerf-dem with material.base by path"; }
grep -q '"git_commit"' "$tmp/dem/summary.json" || fail "summary.json has no provenance"
python3 - "$tmp/dem/summary.json" <<'PY' || exit 1
import json, sys
p = json.load(open(sys.argv[1]))["provenance"]
for key in ("version", "git_commit", "command_line", "scene", "scene_fnv1a64", "overrides", "date", "host", "threads"):
    assert key in p, key
assert p["command_line"].split()[1:3] == ["run", p["scene"]], p["command_line"]
assert len(p["scene_fnv1a64"]) == 16 and p["threads"] == 1 and len(p["overrides"]) == 7
PY
"$dem" --version | grep -Eq '^kerf-dem [0-9]+\.[0-9]+\.[0-9]+' || fail "kerf-dem --version"
echo "material checks passed"
