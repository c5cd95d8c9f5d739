# The figures kerf draws, one command per kind (sourced by tests/cli/figures_canvas.sh and scripts/gallery.sh, not
# a test itself). figure_steps: "name|command", the command as a user types it from the source directory, with
# build/tools/ for the programs and out/gallery/ for the output; each DEM scene shrunk with --set to seconds on
# one thread (the numbers on those figures are not results: the specimens are tiny).
# draw_figures <dir of built programs> <source dir> <out dir>: runs every step from the source dir, each with its
# log as <out dir>/<name>.log; on a failing step prints its name and log's tail and returns 1.
dem_small="--set specimen.width_mm=0.2 --set specimen.height_mm=0.4 --set specimen.growth_steps=2000 \
--set specimen.relax_steps=500"
dem_lab="$dem_small --set loading.quasi_static_check=false --set loading.speed_m_per_s=0.1 \
--set output.frame_every_samples=0 --threads 1"
figure_steps=(
  "forces_sweep|build/tools/kerf-forces sweep data/scenes/psic_orthogonal.json \
--vary cut.uncut_chip_thickness_um=0.01:1:20:log --vary tool.edge_radius_um=0,0.5,2 --csv out/gallery/forces_sweep.csv \
--plot out/gallery/forces_sweep.png"
  "glass_sweep|build/tools/kerf-forces sweep data/scenes/soda_lime_transition.json \
--vary cut.uncut_chip_thickness_um=0.01:200:25:log --vary tool.edge_radius_um=0,2,20 --csv out/gallery/glass_sweep.csv \
--plot out/gallery/glass_sweep.png"
  "materials_sweep|build/tools/kerf-forces sweep data/scenes/soda_lime_transition.json \
--vary cut.uncut_chip_thickness_um=0.01:1:10:log --vary material=soda_lime_glass,k9_glass \
--csv out/gallery/materials_sweep.csv --plot out/gallery/materials_sweep.png"
  "compare|build/tools/kerf-forces compare validation/k9_trepanning/scene.json \
--experiments data/experiments/k9_trepanning.csv --map cut.feed_rate_um_per_s=feed_rate_um_s \
--map axial_force_N=axial_force_test_N --map torque_N_m=torque_test_Nm --fit --out out/gallery/compare"
  "report|build/tools/kerf-forces report data/comparisons/soda_lime_dem_vs_experiment.json --out out/gallery/report"
  "specimen|build/tools/kerf-dem run data/scenes/dem_specimen.json $dem_small --threads 1 --out out/gallery/specimen"
  "tension|build/tools/kerf-dem run data/scenes/dem_tension.json $dem_lab --out out/gallery/tension"
  "compression|build/tools/kerf-dem run data/scenes/dem_compression.json $dem_lab --out out/gallery/compression"
  "cut|build/tools/kerf-dem run data/scenes/dem_cut.json --set specimen.width_mm=0.4 --set specimen.height_mm=0.25 \
--set specimen.growth_steps=2000 --set specimen.relax_steps=500 --set cut.depth_of_cut_mm=0.05 --set cut.length_mm=0.04 \
--set cut.speed_m_per_s=2 --set output.frame_every_samples=200 --set output.frame_png=true --threads 1 --out out/gallery/cut"
  "toughness|build/tools/kerf-dem run data/scenes/dem_toughness.json --set specimen.width_mm=0.86 \
--set specimen.height_mm=0.2 --set specimen.growth_steps=2000 --set specimen.relax_steps=500 \
--set toughness.notch_depth_mm=0.08 --set toughness.roller_radius_mm=0.03 --set toughness.speed_m_per_s=0.05 \
--set toughness.quasi_static_check=false --replicates 2 --threads 1 --out out/gallery/toughness"
  "study|build/tools/kerf-dem study data/studies/smoke.json --threads 1 --out out/gallery/study"
  "study_list|build/tools/kerf-dem study data/studies/smoke_glasses.json --threads 1 --out out/gallery/study_list"
)

draw_figures() {
  local bin_dir=$1 src=$2 out=$3 step name command
  mkdir -p "$out"
  for step in "${figure_steps[@]}"; do
    name=${step%%|*}
    command=${step#*|}
    command=${command//build\/tools\//$(printf %q "$bin_dir")/}
    command=${command//out\/gallery\//$(printf %q "$out")/}
    if ! (cd "$src" && export KERF_DATA_DIR="$src/data" OMP_NUM_THREADS=1 && eval "$command") >"$out/$name.log" 2>&1; then
      echo "$name failed: $(tail -3 "$out/$name.log")"
      return 1
    fi
  done
}
