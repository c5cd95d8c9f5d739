#!/usr/bin/env bash
# Every kind of PNG figure kerf draws, at its default size, with nothing run off the canvas (issue 55 item 4):
# the commands of tests/cli/lib/figures.sh (kerf-forces sweep --plot with a numeric, a log and a categorical second
# key, compare's and report's parity and trend figures, kerf-dem's specimen, tension and compression curves and
# specimens, a cut's forces, specimen and frame pictures, toughness curve, specimen and crack, a study's plots and
# its items' figures, a list study's plots by condition), each shrunk to seconds; then lib/canvas_edge.py finds any
# PNG whose outer 2-pixel frame is not all background (a title, axis or tick label, or legend that runs off the
# edge). That it can fail was checked
# by hand (2026-12-06): it failed on a figure with PIL text drawn at the edge, on a copy of forces.png cropped by
# 40 pixels, and on 7 real figures before the fix in src/plot.cpp (a report's "a_c (mm)" subscript at the bottom
# edge; a study's tick labels 0.20006 and a "(10^-6)" superscript at the left edge; a sweep's legend with
# "material = soda_lime_glass" past the right edge).
# Usage: figures_canvas.sh <dir of built programs> <source dir>
set -uo pipefail
bin_dir="$1"; src="$2"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
python=/usr/bin/python3; [ -x "$python" ] || python=python3
"$python" -c "import numpy, PIL" 2>/dev/null || fail "$python has no numpy or PIL (scripts/install-deps.sh installs them)"
source "$src/tests/cli/lib/figures.sh"

draw_figures "$bin_dir" "$src" "$work/fig" || fail "a figure's command failed (above)"
mapfile -t pngs < <(find "$work/fig" -name "*.png" | sort)
# One of each kind at least (a figure a command stopped drawing is a failure too).
for f in forces_sweep.png glass_sweep.png materials_sweep.png compare/parity_axial_force.png \
         compare/axial_force_vs_feed_rate.png report/parity_main_force_per_width.png report/main_force_vs_depth_of_cut.png \
         specimen/specimen.png tension/curve.png tension/specimen.png compression/curve.png compression/specimen.png \
         cut/forces.png cut/specimen.png cut/frame_0000.png toughness/curve.png toughness/specimen.png toughness/crack.png \
         study/plots/tensile_strength_MPa_vs_loading_speed_m_per_s.png study/items/condition_1_seed_1/curve.png \
         study_list/plots/tensile_strength_MPa_by_condition.png; do
  [ -s "$work/fig/$f" ] || fail "no $f among: ${pngs[*]#$work/fig/}"
done
"$python" "$src/tests/cli/lib/canvas_edge.py" "${pngs[@]}" || fail "a figure runs off its canvas (above)"
echo "PASS: ${#pngs[@]} figures, none runs off its canvas"
