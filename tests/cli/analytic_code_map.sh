#!/usr/bin/env bash
# The code map of docs/analytic-models.md matches the folders (issue 39), as dem_code_map.sh checks docs/dem.md's:
# every name in its table's first column is a file (`scene`: analytic/scene.cpp or include/kerf/analytic/scene.hpp;
# `orthogonal_kind.cpp`: that file under analytic/ or include/kerf/analytic/; a name with a '/': that path from the
# source root), and every source under analytic/ and header under include/kerf/analytic/ is named by a row.
# Usage: bash analytic_code_map.sh <bin dir (unused)> <source dir>. Needs python3 only: no build.
set -uo pipefail
src="$2"
python3 - "$src" <<'PY'
import pathlib, re, sys
src = pathlib.Path(sys.argv[1])
text = (src / "docs/analytic-models.md").read_text()
section = text[text.index("## Code map"):]
section = section[:section.index("\n## ", 1)]
names = []
for line in section.split("\n"):
    if line.startswith("| `"):
        names += re.findall(r"`([^`]+)`", line.split("|")[1])
sources = sorted(p.name for p in (src / "analytic").glob("*.cpp"))
headers = sorted(p.name for p in (src / "include/kerf/analytic").glob("*.hpp"))

def covers(name, file):
    return file == name if name.endswith((".cpp", ".hpp")) else file in (name + ".cpp", name + ".hpp")

failures = 0
for n in names:
    found = (src / n).is_file() if "/" in n else any(covers(n, f) for f in sources + headers)
    if not found:
        print(f"FAIL: the code map names `{n}`, which is no file"); failures += 1
for folder, files in (("analytic", sources), ("include/kerf/analytic", headers)):
    for f in files:
        if not any(covers(n, f) for n in names if "/" not in n):
            print(f"FAIL: {folder}/{f} is not in the code map of docs/analytic-models.md"); failures += 1
print(f"{len(names)} names, {len(sources)} sources, {len(headers)} headers; {failures} failures")
sys.exit(1 if failures else 0)
PY
