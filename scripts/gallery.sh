#!/usr/bin/env bash
# Redraws docs/img/gallery/*.png and docs/gallery.md (issue 55 item 4): one of every kind of figure kerf draws, at
# its default size, from the commands of tests/cli/lib/figures.sh (the ones tests/cli/figures_canvas.sh checks for
# labels run off the canvas), each DEM scene shrunk to seconds. The PNGs are copied as kerf wrote them.
#   bash scripts/gallery.sh [dir of built programs, default build/tools]
# Needs the built kerf-forces and kerf-dem, and python3 with numpy and PIL for the canvas check (a warning if a
# figure fails it; the page is written anyway).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin_dir="$(cd "${1:-$root/build/tools}" && pwd)"
for p in kerf-forces kerf-dem; do
  [ -x "$bin_dir/$p" ] || { echo "scripts/gallery.sh: error: no $bin_dir/$p (build first: bash scripts/build.sh)" >&2; exit 2; }
done
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
source "$root/tests/cli/lib/figures.sh"
draw_figures "$bin_dir" "$root" "$work" || exit 1

# step|figure the step wrote|name in docs/img/gallery|what it shows (one line)
figures=(
  "forces_sweep|forces_sweep.png|forces_sweep.png|cutting (solid) and thrust (dashed) force against the first varied key on a log axis, a colour per value of the second; the critical depth d_c marked; hollow markers where the model is outside its range"
  "glass_sweep|glass_sweep.png|glass_sweep.png|glass from 10 nm to 0.2 mm with models.force = transition: the ductile layer below d_c, the layer and fracture above"
  "materials_sweep|materials_sweep.png|materials_sweep.png|a categorical second key (two materials): the legend beside the axes names each value and marks each material's d_c"
  "compare|compare/parity_axial_force.png|compare_parity.png|parity plot: predicted against measured, y = x and a ±10 % band (rows outside the model's range, where there are any, hollow)"
  "compare|compare/axial_force_vs_feed_rate.png|compare_trend.png|a quantity against one condition: the measured points (one series per value of the other condition) and the model's line"
  "report|report/parity_main_force.png|report_parity.png|a comparison file's parity plot: two data sets held against each other, ±1 SD error bars on both"
  "report|report/main_force_vs_depth_of_cut.png|report_trend.png|a comparison file's trend: measured (filled) and predicted (hollow, drawn slightly to the right) per surface"
  "specimen|specimen/specimen.png|dem_specimen.png|a generated specimen: the disks, in mm"
  "tension|tension/curve.png|dem_tension_curve.png|direct tension: stress against strain, the secant E over its fit range (dashed on to the peak) and the peak"
  "tension|tension/specimen.png|dem_tension_specimen.png|the tension specimen's final state: the held disks grey, the cracks (red tension, blue shear)"
  "compression|compression/curve.png|dem_compression_curve.png|uniaxial compression: stress against strain, the secant E and the peak"
  "compression|compression/specimen.png|dem_compression_specimen.png|the compression specimen's final state between its platens (green)"
  "cut|cut/forces.png|dem_cut_forces.png|a cut: cutting and thrust force per mm of width against tool travel, the means dashed over the travel they cover (NOT STEADY on a cut too short to be steady)"
  "cut|cut/specimen.png|dem_cut_specimen.png|the cut's final state: the workpiece's region, the tool (green), the cracks, the held disks"
  "cut|cut/frame_0001.png|dem_cut_frame.png|one of the frames output.frame_png adds to the VTK frames, in the same fixed view"
  "toughness|toughness/curve.png|dem_toughness_curve.png|fracture toughness (SENB): load against load-point deflection, a colour per packing, the averaged peak with K_IC"
  "toughness|toughness/specimen.png|dem_toughness_specimen.png|the notched beam's final state on its rollers"
  "toughness|toughness/crack.png|dem_toughness_crack.png|the notch and the crack, zoomed"
  "study|study/plots/tensile_strength_MPa_vs_loading_speed_m_per_s.png|study_tensile_strength.png|kerf-dem study: a result's mean and 95 % interval over the packings against a varied key"
  "study|study/plots/strain_at_peak_vs_loading_speed_m_per_s.png|study_strain_at_peak.png|a result of small values, drawn in a power of ten said in the axis label"
  "study_list|study_list/plots/tensile_strength_MPa_by_condition.png|study_by_condition.png|a list study (two glasses, named by their tags): a result by condition, a point per condition named in the legend"
)

# The sections' headings, by step.
declare -A heading=(
  [forces_sweep]="kerf-forces sweep --plot" [glass_sweep]="kerf-forces sweep --plot: glass across its transition"
  [materials_sweep]="kerf-forces sweep --plot: a categorical second key" [compare]="kerf-forces compare"
  [report]="kerf-forces report (a comparison file)" [specimen]="kerf-dem run, kind specimen"
  [tension]="kerf-dem run, kind tension" [compression]="kerf-dem run, kind compression" [cut]="kerf-dem run, kind cut"
  [toughness]="kerf-dem run, kind toughness" [study]="kerf-dem study" [study_list]="kerf-dem study: a list study"
)
# wrap_command: a command on lines of at most 116 characters, broken before its options (" \" and 4 spaces).
wrap_command() {
  awk '{ n = split($0, parts, / --/); line = parts[1]
         for (i = 2; i <= n; i++) {
           part = "--" parts[i]
           if (length(line) + 1 + length(part) > 114) { print line " \\"; line = "    " part } else line = line " " part
         }
         print line }'
}
wrap_text() { fold -s -w 118 | sed 's/ *$//'; }

"$(command -v /usr/bin/python3 || command -v python3)" "$root/tests/cli/lib/canvas_edge.py" $(find "$work" -name "*.png") ||
  echo "scripts/gallery.sh: warning: a figure runs off its canvas (above)" >&2

out="$root/docs/img/gallery"
rm -rf "$out"; mkdir -p "$out"
page="$root/docs/gallery.md"
{
  echo "# Figure gallery"
  echo
  echo "Every kind of figure kerf draws, at its default size (each PNG has a PDF of the same drawing beside it), redrawn"
  echo "by \`bash scripts/gallery.sh\` from the commands below, which tests/cli/figures_canvas.sh also runs to check that"
  echo "no title, label or legend runs off the canvas. The DEM scenes are shrunk to seconds with \`--set\`: the numbers"
  echo "on those figures are not results. How to read each output: [guide.md](guide.md)."
  last=""
  for entry in "${figures[@]}"; do
    IFS='|' read -r step file name what <<<"$entry"
    cp "$work/$file" "$out/$name"
    if [ "$step" != "$last" ]; then
      for s in "${figure_steps[@]}"; do [ "${s%%|*}" = "$step" ] && command=${s#*|}; done
      echo
      echo "## ${heading[$step]}"
      echo
      echo '```sh'
      wrap_command <<<"$command"
      echo '```'
      last=$step
    fi
    echo
    echo "![$step: $(basename "$file")](img/gallery/$name)"
    echo
    wrap_text <<<"\`$(basename "$file")\`: $what."
  done
} >"$page"
echo "wrote $page and ${#figures[@]} figures in $out ($(du -sh "$out" | cut -f1))"
