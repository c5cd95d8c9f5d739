#!/usr/bin/env bash
# The code map of docs/dem-code-map.md (its section "The folders") matches the folders (issue 39): every name in
# its table's first column is a file (`engine/simulation`: dem/engine/simulation.cpp or
# include/kerf/dem/engine/simulation.hpp; `kinds/common.*`: any extension; `laws/contact_laws.hpp`: under dem/ or
# include/kerf/dem/), and every source and header of the DEM (dem/**/*.cpp, dem/**/*.hpp, include/kerf/dem/**/*.hpp)
# is named by a row. A public header mirrors its source's path.
# Usage: bash dem_code_map.sh <bin dir (unused)> <source dir>. Needs python3 only: no build.
set -uo pipefail
src="$2"
python3 - "$src" <<'PY'
import pathlib, re, sys
src = pathlib.Path(sys.argv[1])
text = (src / "docs/dem-code-map.md").read_text()
section = text[text.index("## The folders"):]
section = section[:section.index("\n## ", 1)] if "\n## " in section[1:] else section
names = []
for line in section.split("\n"):
    if line.startswith("| `"):
        names += re.findall(r"`([^`]+)`", line.split("|")[1])
dem, inc = src / "dem", src / "include/kerf/dem"
files = sorted(p.relative_to(dem).as_posix() for p in dem.rglob("*") if p.suffix in (".cpp", ".hpp"))
headers = sorted(p.relative_to(inc).as_posix() for p in inc.rglob("*.hpp"))

def covers(name, rel):  # rel: a path under dem/ or include/kerf/dem/
    if name.endswith(".*"):
        return rel.rsplit(".", 1)[0] == name[:-2]
    if name.endswith((".cpp", ".hpp")):
        return rel == name
    return rel in (name + ".cpp", name + ".hpp")

failures = 0
for n in names:
    if not any(covers(n, f) for f in files) and not any(covers(n, h) for h in headers):
        print(f"FAIL: the code map names `{n}`, which is no file under dem/ or include/kerf/dem/"); failures += 1
for f in files:
    if not any(covers(n, f) for n in names):
        print(f"FAIL: dem/{f} is not in the code map of docs/dem-code-map.md"); failures += 1
for h in headers:
    if not any(covers(n, h) for n in names):
        print(f"FAIL: include/kerf/dem/{h} is not in the code map of docs/dem-code-map.md"); failures += 1
    elif not (dem / (h[:-4] + ".cpp")).exists() and h not in names:  # header only: named with its extension
        print(f"FAIL: include/kerf/dem/{h} has no source dem/{h[:-4]}.cpp, and the map does not name it as a header")
        failures += 1
print(f"{len(names)} names, {len(files)} files under dem/, {len(headers)} headers under include/kerf/dem/; "
      f"{failures} failures")
sys.exit(1 if failures else 0)
PY
