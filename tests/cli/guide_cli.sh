#!/usr/bin/env bash
# The user guide's tasks run as written (issue 40): every ```sh block of docs/guide.md, in order, from a scratch
# directory laid out as the repository root (the source tree's entries linked in, build/ the build tree, a fresh
# out/), each block as one bash script with -e and pipefail. A ```sh long block (minutes, or MPI) is not run; the
# ```python guide block runs in tests/python/test_guide_notebook.py.
# Usage: guide_cli.sh <dir of built programs> <source dir>
set -uo pipefail
bindir="$(cd "$1" && pwd)"; src="$(cd "$2" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
export OMP_NUM_THREADS=1 KERF_DATA_DIR="$src/data"

for entry in "$src"/*; do
  case "$(basename "$entry")" in build|out) ;; *) ln -s "$entry" "$work/$(basename "$entry")" ;; esac
done
ln -s "$(dirname "$bindir")" "$work/build"   # the programs' directory is build/tools

# Blocks: "```sh" opens one to run, "```sh long" one to skip; each written to blocks/N.sh.
mkdir -p "$work/.blocks"
awk -v dir="$work/.blocks" '
  /^```sh[ \t]*$/ { n++; file = sprintf("%s/%02d.sh", dir, n); inblock = 1; next }
  /^```sh[ \t]+long[ \t]*$/ { skipped++; inblock = 2; next }
  /^```/ && inblock { inblock = 0; next }
  inblock == 1 { print > file }
  END { printf "%d %d\n", n, skipped > (dir "/count") }' "$src/docs/guide.md"
read -r run skipped <"$work/.blocks/count"
[ "$run" -ge 8 ] || fail "docs/guide.md: expected at least 8 \`\`\`sh blocks, found $run"

cd "$work" || fail "no scratch directory"
for block in .blocks/[0-9]*.sh; do
  start=$SECONDS
  if ! bash -e -o pipefail "$block" >"$work/.log" 2>&1; then
    echo "--- block $(basename "$block" .sh) of docs/guide.md:"; cat "$block"; echo "--- its output (tail):"
    tail -20 "$work/.log"
    fail "docs/guide.md: block $(basename "$block" .sh) failed"
  fi
  echo "block $(basename "$block" .sh): ok in $((SECONDS - start)) s ($(head -1 "$block" | cut -c1-70))"
done

# What the guide says each task leaves behind.
for f in out/guide/one.csv out/guide/sweep.csv out/guide/sweep.png out/guide/predict.csv out/guide/k9/report.md \
         out/guide/specimen/specimen.json out/guide/calibrate/my_glass.json out/guide/calibrate5/my_tough_glass.json \
         out/guide/cut/forces.csv \
         out/guide/cut/cracks.csv out/guide/cut/forces.png out/guide/cut/result.pvd out/guide/smoke/conditions.csv; do
  [ -s "$f" ] || fail "docs/guide.md promises $f; it is missing or empty"
done
head -1 out/guide/predict.csv | grep -q '^force_model,' || fail "predict --csv - > file: not a CSV: $(head -1 out/guide/predict.csv)"
python3 -c "import json, sys; r = json.load(open('out/guide/cut/summary.json'))['results']
sys.exit(0 if r['steady'] is False and 'within the entry' in r['not_steady_reason'] else 1)" ||
  fail "the guide's short cut must say NOT STEADY (within the entry), as the guide explains"
# Every field of results the guide's table names exists in a cut's summary.json.
for field in $(sed -n '/^The fields of `results`/,/^With `--replicates N`/p' "$src/docs/guide.md" | grep '^| `' | cut -d'|' -f2 |
               grep -o '`[a-z_]*`' | tr -d '`'); do
  python3 -c "import json, sys; sys.exit('$field' not in json.load(open('out/guide/cut/summary.json'))['results'])" ||
    fail "docs/guide.md names results.$field, which a cut's summary.json does not have"
done
echo "guide cli: ok ($run blocks run, $skipped long blocks not run)"
