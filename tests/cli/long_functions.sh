#!/usr/bin/env bash
# No C++ function anywhere in kerf (every folder with C++: src, analytic, dem, include, tools, validation, bench,
# tests, fuzz, python) over 80 lines without a reason in a comment just above it (issues 39 and 56: "Long (...) for a
# reason: ..."), as scripts/long-functions.py lists them.
# Usage: bash long_functions.sh <bin dir (unused)> <source dir>. Needs python3 only: no build.
set -uo pipefail
src="$2"
folders="src analytic dem include tools validation bench tests fuzz python"
list=$(cd "$src" && python3 scripts/long-functions.py $folders) ||
  { echo "FAIL: long-functions.py"; exit 1; }
echo "$list"
if grep -q 'NO REASON$' <<<"$list"; then
  echo "FAIL: a function over 80 lines without a reason (a comment 'Long (...) for a reason: ...' above it)"
  exit 1
fi
echo "$(grep -c . <<<"$list") functions over 80 lines, each with its reason"
