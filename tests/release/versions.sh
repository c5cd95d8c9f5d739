#!/usr/bin/env bash
# One version everywhere: kerf-forces --version, kerf-dem --version and kerf.__version__ (when the Python module
# is built) give CMakeLists.txt's project() VERSION, and so do CHANGELOG.md's newest release heading and
# CITATION.cff's version; the licence CITATION.cff names is the one LICENSE holds.
# Usage: versions.sh BIN_DIR SOURCE_DIR CMAKE_VERSION [PYTHON MODULE_DIR]
set -euo pipefail
bin="$1" src="$2" want="$3" python="${4:-}" module_dir="${5:-}"
fail() { echo "FAIL: $*" >&2; exit 1; }

# The version of CMakeLists.txt as written, so that a stale build directory cannot hide a bump.
written="$(sed -nE 's/^project\(kerf VERSION ([0-9]+\.[0-9]+\.[0-9]+).*/\1/p' "$src/CMakeLists.txt")"
[ "$written" = "$want" ] || fail "CMakeLists.txt says '$written', the build was configured with '$want' (re-run cmake)"

for program in kerf-forces kerf-dem; do
  line="$("$bin/$program" --version)"
  pattern="^$program ([0-9.]+)( \(git [^)]+\))?\$"
  [[ "$line" =~ $pattern ]] || fail "$program --version: '$line'"
  [ "${BASH_REMATCH[1]}" = "$want" ] || fail "$program --version gives ${BASH_REMATCH[1]}, CMake $want"
done

if [ -n "$python" ]; then
  got="$(PYTHONPATH="$module_dir" "$python" -c 'import kerf; print(kerf.__version__)')"
  [ "$got" = "$want" ] || fail "kerf.__version__ is '$got', CMake $want"
fi

# The newest release heading: "## [X.Y.Z] - YYYY-MM-DD".
newest="$(grep -m1 -E '^## \[[0-9]+\.[0-9]+\.[0-9]+\]' "$src/CHANGELOG.md" || true)"
heading='^## \[([0-9.]+)\] - ([0-9]{4}-[0-9]{2}-[0-9]{2})$'
[[ "$newest" =~ $heading ]] || fail "CHANGELOG.md's newest release: '$newest'"
[ "${BASH_REMATCH[1]}" = "$want" ] || fail "CHANGELOG.md's newest release is ${BASH_REMATCH[1]}, CMake $want"
released="${BASH_REMATCH[2]}"

cff="$src/CITATION.cff"
grep -qx 'cff-version: 1.2.0' "$cff" || fail "CITATION.cff: no 'cff-version: 1.2.0'"
grep -qx "version: $want" "$cff" || fail "CITATION.cff: version is '$(grep -m1 '^version:' "$cff")', CMake $want"
grep -qx "date-released: $released" "$cff" ||
  fail "CITATION.cff: '$(grep -m1 '^date-released:' "$cff")', CHANGELOG.md's $want is dated $released"
grep -qx 'license: GPL-3.0-or-later' "$cff" || fail "CITATION.cff: licence is not GPL-3.0-or-later"
head -2 "$src/LICENSE" | grep -q 'GNU GENERAL PUBLIC LICENSE' && grep -q 'Version 3, 29 June 2007' "$src/LICENSE" ||
  fail "LICENSE is not the GPL, version 3"
echo "versions agree: $want ($released)"
