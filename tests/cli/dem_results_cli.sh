#!/usr/bin/env bash
# kerf-dem results: the result tables in docs/dem-keys.md and the Python module of their keys
# (python/kerf/result_keys.py) are the ones generated from the result tables (regenerate: build/tools/kerf-dem results,
# pasted between the markers; build/tools/kerf-dem results --python > python/kerf/result_keys.py); each key with a unit
# ends in its unit's suffix; docs/guide.md's curated tables of a cut's outputs name only keys and columns that exist.
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
# docs/guide.md's tables of a cut's outputs (4.4), curated prose, name only what kerf-dem writes: each CSV file's
# columns as its table lists them, in order; each key the results table names (a pattern with * or ...: some key it
# matches) one of a cut's results. A doctored guide naming a key that does not exist fails the check.
check_guide() {  # check_guide GUIDE
  python3 - "$work/results.md" "$1" <<'PY'
import fnmatch, re, sys

results_md, guide_md = sys.argv[1], sys.argv[2]
# kerf-dem results: each section "#### `name`", its where-line, then its table's rows "| `key` | unit | meaning |".
sections, current = [], None
for line in open(results_md):
    if line.startswith("#### `"):
        current = {"name": line.strip()[6:-1], "where": None, "keys": []}
        sections.append(current)
    elif current is not None and current["where"] is None and line.strip():
        current["where"] = line.strip()
    elif current is not None and line.startswith("| `"):
        current["keys"].append(line.split("`")[1])


def table(name, kind):
    """The keys of section `name` of the scene kind `kind` (its where-line: "cut, tension: ...")."""
    found = [s["keys"] for s in sections
             if s["name"] == name and kind in [k.strip() for k in s["where"].split(":")[0].split(",")]]
    if len(found) != 1:
        sys.exit(f"kerf-dem results: no single section {name} for {kind}")
    return found[0]


cut_results = table("results", "cut")
columns = {"forces.csv": table("forces.csv", "cut"), "cracks.csv": table("cracks.csv", "cut")}
# Values the guide's tables quote, not keys.
values = {"batch_means", "autocorrelation", "none", "true", "false"}
text = open(guide_md).read()
start = text.index("### 4.4 Reading every output of a cut")
part = text[start:text.index("\n## ", start)]
rows = [[c.strip() for c in line.strip().strip("|").split("|")] for line in part.splitlines()
        if line.startswith("| ") and not line.startswith("|---")]
bad, checked = [], 0


def known(token, names):
    """A key or column `token` names (a pattern with * or ...: one it matches)."""
    if "*" in token or "..." in token:
        return any(fnmatch.fnmatch(n, token.replace("...", "*")) for n in names)
    return token in names


for cells in rows:
    if cells[0] in ("file", "field"):
        continue
    file = cells[0].strip("`")
    if cells[:1] and len(cells) == 3:  # the files table: a CSV file's columns, in order, as the program writes them
        if file not in columns:
            continue
        tokens = re.findall(r"`([^`]+)`", cells[1])
        listed = [t for t in tokens if "," in t]
        if listed != [",".join(columns[file])]:
            bad.append(f"{file}: the guide lists {listed}, kerf-dem writes {','.join(columns[file])}")
        for t in tokens:
            if "," not in t and not known(t, columns[file] + cut_results):
                bad.append(f"{file}: `{t}` is neither one of its columns nor a result")
        checked += 1
    else:  # the fields of results: every key it names, in either column
        for t in re.findall(r"`([^`]+)`", cells[0]):
            checked += 1
            if not known(t, cut_results):
                bad.append(f"results: `{t}` is no key of a cut's results")
        for t in re.findall(r"`([a-z0-9_.*]+)`", cells[1]):
            if "." in t.replace("...", "") or t in values:  # an input key (cut.window_mm) or a value
                continue
            checked += 1
            if not known(t, cut_results):
                bad.append(f"results: `{t}` (in its meaning) is no key of a cut's results")
if bad or checked < 20:
    sys.exit("docs/guide.md, 4.4: " + ("; ".join(bad) if bad else f"only {checked} names found: the tables moved?"))
print(f"guide: {checked} names checked")
PY
}
check_guide "$src/docs/guide.md" >"$work/guide_check" 2>&1 || fail "$(cat "$work/guide_check")"
sed 's/^| `cracks_tensile`, /| `cracks_tensile`, `cracks_sideways`, /' "$src/docs/guide.md" >"$work/guide_bad.md"
check_guide "$work/guide_bad.md" >"$work/guide_check" 2>&1 && fail "the guide's check passes a key that does not exist"
grep -q "cracks_sideways" "$work/guide_check" ||
  fail "the guide's check does not name the key: $(cat "$work/guide_check")"
sed 's/`time_s,x_mm,y_mm,orientation_deg,length_um,mode,bond,element,place`/`time_s,x_mm,y_mm,length_um`/' \
  "$src/docs/guide.md" >"$work/guide_bad.md"
check_guide "$work/guide_bad.md" >"$work/guide_check" 2>&1 && fail "the guide's check passes a wrong cracks.csv header"
# docs/dem.md's "Outputs" lists cracks.csv's columns (but a cut's place) and a lab test's curve.csv's as written.
python3 - "$work/results.md" "$src/docs/dem.md" <<'PY' || fail "docs/dem.md's column lists differ from kerf-dem results"
import sys
sections = open(sys.argv[1]).read().split("#### `")[1:]
def columns(name, kinds):
    [s] = [s for s in sections if s.startswith(name + "`") and s.split("\n")[2].startswith(kinds)]
    return [line.split("`")[1] for line in s.splitlines() if line.startswith("| `")]
doc = open(sys.argv[2]).read()
for listed in (columns("cracks.csv", "cut, tension")[:-1], columns("curve.csv", "tension, compression")):
    if "`" + ",".join(listed) + "`" not in doc:
        sys.exit(f"docs/dem.md does not list {','.join(listed)}")
PY
echo "dem results cli: ok"
