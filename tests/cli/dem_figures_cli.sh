#!/usr/bin/env bash
# kerf-dem's figures (issue 23 item 4): a tension or compression test draws its stress-strain curve
# (curve.png: the secant E over its fit range and the peak marked, named in the legend); every PNG has a PDF
# of the same drawing beside it (specimen, curve; a cut's forces).
# Usage: dem_figures_cli.sh <dir of built programs> <source dir>
source "$(dirname "$0")/lib/dem_common.sh" "$@"

small=(--set specimen.width_mm=0.2 --set specimen.height_mm=0.4 --set specimen.growth_steps=2000
       --set specimen.relax_steps=500 --set loading.quasi_static_check=false --set loading.speed_m_per_s=0.1
       --set output.frame_every_samples=0)
for kind in tension compression; do
  "$bin" run "$src/data/scenes/dem_$kind.json" "${small[@]}" --out "$work/$kind" --threads 1 >/dev/null 2>"$work/err" ||
    fail "$kind run: $(cat "$work/err")"
  for f in curve specimen; do
    head -c 8 "$work/$kind/$f.png" | od -An -c | grep -q "P   N   G" || fail "$kind: $f.png is not a PNG"
    head -c 5 "$work/$kind/$f.pdf" | grep -q "^%PDF-" || fail "$kind: no $f.pdf beside $f.png"
  done
  ! ls "$work/$kind"/*.tmp-* >/dev/null 2>&1 || fail "$kind: temporary files left"
done
cut=(--set specimen.width_mm=0.4 --set specimen.height_mm=0.25 --set specimen.growth_steps=2000
     --set specimen.relax_steps=500 --set cut.depth_of_cut_mm=0.05 --set cut.length_mm=0.04
     --set output.frame_every_samples=0 --set cut.speed_m_per_s=2)
"$bin" run "$src/data/scenes/dem_cut.json" "${cut[@]}" --out "$work/cut" --threads 1 >/dev/null 2>"$work/err" ||
  fail "cut run: $(cat "$work/err")"
for f in forces specimen; do
  head -c 5 "$work/cut/$f.pdf" | grep -q "^%PDF-" || fail "cut: no $f.pdf beside $f.png"
done
echo "dem figures: ok"
