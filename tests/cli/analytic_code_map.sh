#!/usr/bin/env bash
# The code map of docs/analytic-models.md matches the folders (issue 39; rooms, issue 56), as dem_code_map.sh checks
# docs/dem-code-map.md's: every name in its table's first column is a file (`kinds/scene`: analytic/kinds/scene.cpp
# or include/kerf/analytic/kinds/scene.hpp; `kinds/orthogonal_kind.cpp`: that file under analytic/ or
# include/kerf/analytic/; a name outside them, `tools/kerf_forces.cpp`: that path from the source root), and every
# source under analytic/ and header under include/kerf/analytic/ is named by a row. A public header mirrors its
# source's path.
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
lib, inc = src / "analytic", src / "include/kerf/analytic"
sources = sorted(p.relative_to(lib).as_posix() for p in lib.rglob("*") if p.suffix in (".cpp", ".hpp"))
headers = sorted(p.relative_to(inc).as_posix() for p in inc.rglob("*.hpp"))
outside = [n for n in names if n.split("/")[0] in ("tools", "python")]

def covers(name, rel):  # rel: a path under analytic/ or include/kerf/analytic/
    return rel == name if name.endswith((".cpp", ".hpp")) else rel in (name + ".cpp", name + ".hpp")

failures = 0
for n in names:
    found = (src / n).is_file() if n in outside else any(covers(n, f) for f in sources + headers)
    if not found:
        print(f"FAIL: the code map names `{n}`, which is no file"); failures += 1
for folder, files in (("analytic", sources), ("include/kerf/analytic", headers)):
    for f in files:
        if not any(covers(n, f) for n in names if n not in outside):
            print(f"FAIL: {folder}/{f} is not in the code map of docs/analytic-models.md"); failures += 1
for h in headers:
    if not (lib / (h[:-4] + ".cpp")).exists() and h not in names:
        print(f"FAIL: include/kerf/analytic/{h} has no source analytic/{h[:-4]}.cpp, and the map does not name it "
              "as a header"); failures += 1
print(f"{len(names)} names, {len(sources)} sources, {len(headers)} headers; {failures} failures")
sys.exit(1 if failures else 0)
PY
