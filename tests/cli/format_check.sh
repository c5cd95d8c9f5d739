#!/usr/bin/env bash
# Every C++ source and header (*.cpp, *.hpp, *.h, *.cc: git ls-files in the source directory, or, outside a git
# checkout, every such file but under build*/ and hidden directories) is laid out as .clang-format says (issue 56
# item 4): clang-format --dry-run -Werror, and the files that deviate are named. Apply the layout with
#   git ls-files '*.cpp' '*.hpp' '*.h' '*.cc' | xargs clang-format -i
# Usage: bash format_check.sh <bin dir (unused)> <source dir>. Needs clang-format only (Debian: clang-format,
# which scripts/install-deps.sh installs): no build.
set -uo pipefail
src="$2"
fail() { echo "FAIL: $*"; exit 1; }
command -v clang-format >/dev/null ||
  fail "clang-format is not installed: install it (Debian: apt-get install clang-format, or bash scripts/install-deps.sh)"
[ -f "$src/.clang-format" ] || fail "$src/.clang-format is missing"
cd "$src" || fail "cannot enter $src"
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h' '*.cc' | while IFS= read -r f; do [ -f "$f" ] && echo "$f"; done)
else
  mapfile -t files < <(find . \( -type d \( -name 'build*' -o -name '.?*' \) -prune \) -o -type f \
    \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' -o -name '*.cc' \) -print | sed 's|^\./||' | sort)
fi
[ ${#files[@]} -gt 0 ] || fail "no C++ file found under $src"
out=$(printf '%s\0' "${files[@]}" | xargs -0 clang-format --dry-run -Werror 2>&1)
rc=$?
deviating=$(grep -oE '^[^:]+:[0-9]+:[0-9]+: error: code should be clang-formatted' <<<"$out" | cut -d: -f1 | sort -u)
if [ -n "$deviating" ]; then
  echo "$deviating" | sed 's/^/deviates: /'
  fail "$(grep -c . <<<"$deviating") of ${#files[@]} C++ files deviate from .clang-format ($(clang-format --version)):" \
    "apply it with: git ls-files '*.cpp' '*.hpp' '*.h' '*.cc' | xargs clang-format -i"
fi
[ $rc -eq 0 ] || { echo "$out" | tail -20; fail "clang-format exited with status $rc"; }
echo "${#files[@]} C++ files laid out as .clang-format says ($(clang-format --version))"
