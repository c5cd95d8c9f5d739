#!/usr/bin/env bash
# Every citation in code, data and docs resolves inside the repository (issue #19):
# 1. no tracked file names the shared folder beside the repository (the two-dot shared path, or its docs,
#    seeds or data subfolders): a fresh clone does not have it;
# 2. every "physics-dem.md section N", "physics-analytic.md §N" (also "docs/physics-...", "Section", "§ N",
#    a citation broken over two comment lines) names a "## N." heading of docs/physics-dem.md or
#    docs/physics-analytic.md, and a file cited at all exists in docs/;
# 3. no citation names an equation of those notes (the note's name, then "eq." and a number): they number none.
# Usage: bash citations.sh <bin dir (unused)> <source dir>. Needs only bash, grep, sed, awk: no build.
set -uo pipefail
src="$2"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

dirs=(analytic dem src include tools validation tests bench analysis docs data scripts README.md)
files=()
if git -C "$src" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  while IFS= read -r f; do files+=("$f"); done < <(git -C "$src" ls-files -- "${dirs[@]}")
else
  while IFS= read -r f; do files+=("${f#"$src"/}"); done < <(
    for d in "${dirs[@]}"; do [ -e "$src/$d" ] && find "$src/$d" -type f; done | sort)
fi
[ "${#files[@]}" -gt 0 ] || { echo "FAIL: no files found under $src"; exit 1; }

# 1. The shared folder. The patterns are spelt with brackets so that this script does not match itself.
shared_re='[.][.]/shared|shared[/](docs|seeds|data)'
# One grep over every file (a program start per file costs seconds on a slow machine); its lines "SRC/FILE:LINE:TEXT".
paths=("${files[@]/#/$src/}")
while IFS= read -r hit; do
  rel="${hit#"$src"/}" && rest="${rel#*:}"
  fail "${rel%%:*}:${rest%%:*}: cites the shared folder outside the repository: ${rest#*:}"
done < <(grep -I -n -H -E "$shared_re" -- "${paths[@]}" 2>/dev/null)

# Section numbers of a note in docs/: its "## N." headings, as " N N ... ".
sections_of() {
  [ -f "$src/docs/$1" ] || return 0
  echo " $(sed -n -E 's/^## ([0-9]+)\..*/\1/p' "$src/docs/$1" | tr '\n' ' ')"
}
declare -A have
have[physics-dem.md]="$(sections_of physics-dem.md)"
have[physics-analytic.md]="$(sections_of physics-analytic.md)"

# 2 and 3. Each file is read as one line, comment markers at line starts dropped, so that a citation broken
# over two comment lines is still seen; awk prints "note<TAB>kind<TAB>number" for each citation.
# The files that name a note at all, found by one grep.
citing=()
while IFS= read -r path; do citing+=("${path#"$src"/}"); done < <(
  grep -I -l 'physics-\(dem\|analytic\)\.md' -- "${paths[@]}" 2>/dev/null)
for f in "${citing[@]}"; do
  while IFS=$'\t' read -r note kind num; do
    case "$kind" in
      file) [ -f "$src/docs/$note" ] || fail "$f: cites $note, which docs/ does not have" ;;
      eq) fail "$f: cites $note eq. $num, but $note numbers no equations (cite its section)" ;;
      section)
        if [ ! -f "$src/docs/$note" ]; then fail "$f: cites $note section $num, which docs/ does not have"
        elif [[ "${have[$note]}" != *" $num "* ]]; then
          fail "$f: cites $note section $num; docs/$note has sections${have[$note]}"
        fi ;;
    esac
  done < <(awk '
    { line = $0; sub(/^[ \t]*(\/\/\/?|#|\*|<!--)?[ \t]*/, "", line); text = text " " line }
    END {
      while (match(text, /physics-(dem|analytic)\.md/)) {
        note = substr(text, RSTART, RLENGTH); rest = substr(text, RSTART + RLENGTH)
        text = rest
        sub(/^[`*"'\'')]*[ \t]*/, "", rest)
        if (match(rest, /^([Ss]ection|§)[ \t]*[0-9]+/)) {
          s = substr(rest, 1, RLENGTH); gsub(/[^0-9]/, "", s); print note "\tsection\t" s
        } else if (match(rest, /^[Ee]q(uation)?s?\.?[ \t]*[0-9]+/)) {
          s = substr(rest, 1, RLENGTH); gsub(/[^0-9]/, "", s); print note "\teq\t" s
        } else print note "\tfile\t-"
      }
    }' "$src/$f")
done

if [ "$failures" -eq 0 ]; then echo "all citations resolve inside the repository (${#files[@]} files)"; fi
[ "$failures" -eq 0 ]
