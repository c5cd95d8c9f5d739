#!/usr/bin/env bash
# The neighbour search (dem/engine/neighbor_grid.cpp) of commit OLD against the working tree's, alternating in one
# process on synthetic assemblies with fragments flown off (bench/neighbor_search_ab.cpp). CSV on stdout.
#
#   bash bench/neighbor_search_ab.sh OLD_COMMIT > neighbor_search_ab.csv
set -euo pipefail
src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
body() {  # the file's code between its includes and the end of its namespace
  python3 -c 'import sys; s = sys.stdin.read(); print(s[s.index("namespace kerf::dem {") + len("namespace kerf::dem {"):s.rindex("}  // namespace kerf::dem")])'
}
# The file's path at OLD: dem/engine/ since issue 39's folders, dem/ before.
{ git -C "$src" show "$1:dem/engine/neighbor_grid.cpp" 2>/dev/null || git -C "$src" show "$1:dem/neighbor_grid.cpp"; } |
  body > "$tmp/old.inc"
body < "$src/dem/engine/neighbor_grid.cpp" > "$tmp/new.inc"
g++ -std=c++20 -O3 -DNDEBUG -I"$src/include" -DOLD_GRID="\"$tmp/old.inc\"" -DNEW_GRID="\"$tmp/new.inc\"" \
  "$src/bench/neighbor_search_ab.cpp" "$src/src/error.cpp" -lfmt -o "$tmp/ab"
"$tmp/ab"
