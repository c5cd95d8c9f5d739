#!/usr/bin/env bash
# kerf-forces keys: the key tables in docs/scenes.md are the ones generated from the field tables the analytic
# scenes are read with (regenerate: build/tools/kerf-forces keys, each section pasted between its markers; the
# blocks, joined by a blank line, are the whole output). The tables are the parsers' own: a default the table
# prints is the one a scene without the key gets, and a key no table has is refused with a did-you-mean.
# Usage: forces_keys_cli.sh <dir of built programs> <source dir>
set -uo pipefail
bin="$1/kerf-forces"; src="$2"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$bin" keys >"$work/keys.md" || fail "kerf-forces keys failed"
awk '/<!-- kerf-forces keys: begin -->/ { inside = 1; if (n++) print ""; next }
     /<!-- kerf-forces keys: end -->/ { inside = 0; next }
     inside' "$src/docs/scenes.md" >"$work/doc.md"
[ -s "$work/doc.md" ] || fail "docs/scenes.md has no kerf-forces keys blocks"
diff -u "$work/doc.md" "$work/keys.md" >"$work/diff" ||
  fail "docs/scenes.md's key tables differ from kerf-forces keys: $(head -20 "$work/diff")"
for section in material.elastic material.johnson_cook material.thermal material.microstructure material.oxley material.brittle \
  tool cut cut.turning measured models models.quadrature models.flow_stress_policy models.trepanning \
  models.trepanning.grits; do
  grep -q "^#### \`$section\`" "$work/keys.md" || fail "no key table for $section"
done
# One section: its tables only (tool: the orthogonal cut's and the trepanning drill's).
"$bin" keys tool >"$work/tool.md" || fail "keys tool failed"
[ "$(grep -c '^#### ' "$work/tool.md")" -eq 2 ] || fail "keys tool: expected two tables: $(grep '^#### ' "$work/tool.md")"
grep -q '^| `outer_diameter_mm` | mm |' "$work/tool.md" || fail "keys tool: no outer_diameter_mm row"
"$bin" keys tol >/dev/null 2>"$work/err"
[ $? -eq 2 ] || fail "unknown section: expected exit 2"
grep -q "^kerf-forces: error: SECTION = tol: .*did you mean 'tool'" "$work/err" || fail "unknown section: $(cat "$work/err")"

# The default a table prints is the one a scene gets: tool.clearance_deg left out is recorded at its default.
default=$(grep '^| `clearance_deg` |' "$work/tool.md" | awk -F'|' '{gsub(/ /, "", $5); print $5}')
python3 - "$src/data/scenes/psic_orthogonal.json" "$work/scene.json" <<'PY'
import json, re, sys
text = re.sub(r"^\s*//.*$", "", open(sys.argv[1]).read(), flags=re.M)
scene = json.loads(text)
scene["tool"].pop("clearance_deg", None)
json.dump(scene, open(sys.argv[2], "w"))
PY
"$bin" predict "$work/scene.json" --csv "$work/p.csv" >/dev/null 2>&1 || fail "predict without clearance_deg failed"
got=$(python3 -c "import csv,sys; print(next(csv.DictReader(open(sys.argv[1])))['clearance_deg'])" "$work/p.csv")
python3 -c "import sys; sys.exit(abs(float(sys.argv[1]) - float(sys.argv[2])) > 1e-9)" "$got" "$default" ||
  fail "clearance_deg: the table's default is $default, a scene without the key records $got"

# A key of no table is refused, naming the section's key it is nearest to.
"$bin" predict "$src/data/scenes/psic_orthogonal.json" --set models.quadrature.tolerence=1e-6 >/dev/null 2>"$work/err"
[ $? -eq 2 ] || fail "unknown key: expected exit 2"
grep -q "^kerf-forces: error: models.quadrature.tolerence = 1e-06: expected a known key (did you mean 'tolerance'?)" \
  "$work/err" || fail "unknown key: $(cat "$work/err")"
echo "forces keys cli: ok"
