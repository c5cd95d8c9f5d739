#!/usr/bin/env bash
# kerf-forces sweep --plot (issue 55 item 4): a .svg name gets SVG (its first bytes), with a PDF beside it; .pdf a PDF
# alone; '-' or another extension exits 2 before any point runs, naming --plot, and writes nothing.
# Usage: forces_plot_formats.sh <dir of built programs> <source dir>
set -uo pipefail
bin="$1/kerf-forces"; src="$2"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
scene="$src/data/scenes/soda_lime_transition.json"
sweep() { "$bin" sweep "$scene" --vary cut.uncut_chip_thickness_um=0.01:1:4:log --csv "$work/s.csv" "$@"; }

sweep --plot "$work/f.svg" 2>/dev/null || fail "--plot f.svg failed"
head -c 200 "$work/f.svg" | grep -q "<svg" || fail "f.svg is not SVG: $(head -c 40 "$work/f.svg" | od -c | head -2)"
[ "$(head -c 4 "$work/f.pdf")" = "%PDF" ] || fail "no PDF beside the SVG"
sweep --plot "$work/g.pdf" 2>/dev/null || fail "--plot g.pdf failed"
[ "$(head -c 4 "$work/g.pdf")" = "%PDF" ] || fail "g.pdf is not a PDF"
[ -e "$work/g.png" ] && fail "a .pdf figure wrote a PNG too"
rm -f "$work/s.csv"
for bad in - "$work/h.jpg"; do
  (cd "$work" && sweep --plot "$bad" 2>"$work/err"); rc=$?
  [ $rc -eq 2 ] || fail "--plot $bad: exit $rc, want 2"
  grep -q -- "--plot = $bad: expected a figure file named .png, .svg or .pdf" "$work/err" || fail "message: $(cat "$work/err")"
  [ -e "$work/s.csv" ] || [ -e "$work/-" ] || [ -e "$work/-.pdf" ] && fail "--plot $bad wrote files"
done
echo "PASS: figure formats"
