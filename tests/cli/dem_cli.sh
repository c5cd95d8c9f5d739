#!/usr/bin/env bash
# kerf-dem command-line behaviour: bad input exits 2 naming field, value and expectation; a small tension
# run writes complete outputs; the same run on 1 and 2 threads gives identical curves.
# Usage: dem_cli.sh <dir of built programs> <source dir>
source "$(dirname "$0")/lib/dem_common.sh" "$@"

scene="$src/data/scenes/dem_tension.json"
expect_input_error "specimen.radius_min_um = -1: expected a positive value" run "$scene" --set specimen.radius_min_um=-1 --out "$work/x"
expect_input_error "did you mean 'tensile_strength_MPa'" run "$scene" --set material.tensile_strenght_MPa=10 --out "$work/x"
expect_input_error "kind = bending: expected one of" run "$scene" --set kind=bending --out "$work/x"
expect_input_error "material.n_elements = 1" run "$scene" --set material.n_elements=1 --out "$work/x"
expect_input_error "material.base = glas" run "$scene" --set material.base=glas --out "$work/x"
expect_input_error "no_such_scene.json" run "$work/no_such_scene.json" --out "$work/x"
[ ! -e "$work/x/summary.json" ] || fail "a rejected scene wrote output"

small=(--set specimen.width_mm=0.2 --set specimen.height_mm=0.4 --set specimen.growth_steps=2000
       --set specimen.relax_steps=500 --set loading.quasi_static_check=false --set loading.speed_m_per_s=0.1)
"$bin" run "$scene" "${small[@]}" --out "$work/t1" --threads 1 >/dev/null 2>"$work/err" || fail "tension run: $(cat "$work/err")"
head -c 8 "$work/t1/specimen.png" | od -An -c | grep -q "P   N   G" || fail "specimen.png is not a PNG"
[ ! -s "$work/err" ] || fail "quiet expected when stderr is not a terminal, got: $(cat "$work/err")"
for f in summary.json curve.csv cracks.csv result.pvd frame_0000.vtp cracks_0000.vtp specimen.png; do
  [ -s "$work/t1/$f" ] || fail "missing $f"
done
head -1 "$work/t1/curve.csv" | grep -qx "time_s,axial_strain,lateral_strain,stress_MPa,tension_cracks,shear_cracks" || fail "curve header"
# Summary content (plain shell: no interpreter beyond bash and coreutils needed).
value() { grep -o "\"$1\": [-0-9.e+]*" "$work/t1/summary.json" | head -1 | awk '{print $2}'; }
result() { sed -n '/^  "results": {/,/^  }/p' "$work/t1/summary.json" | grep -o "\"$1\": [-0-9.e+]*" | head -1 | awk '{print $2}'; }
in_range() { awk -v x="$1" -v lo="$2" -v hi="$3" 'BEGIN { exit !(x > lo && x < hi) }'; }
in_range "$(result youngs_modulus_GPa)" 20 200 || fail "youngs_modulus_GPa = $(result youngs_modulus_GPa)"
in_range "$(result poissons_ratio)" 0.05 0.45 || fail "poissons_ratio = $(result poissons_ratio)"
in_range "$(result tensile_strength_MPa)" 10 1000 || fail "tensile_strength_MPa = $(result tensile_strength_MPa)"
for k in n_particles steps wall_time_s particle_steps_per_s; do
  in_range "$(value $k)" 0 1e30 || fail "$k missing or not positive"
done
OMP_WAIT_POLICY=passive "$bin" run "$scene" "${small[@]}" --set engine.min_parallel_items=0 --out "$work/t2" --threads 2 >/dev/null 2>&1 || fail "2-thread run"
cmp -s "$work/t1/curve.csv" "$work/t2/curve.csv" || fail "1 and 2 threads differ"
cmp -s "$work/t1/cracks.csv" "$work/t2/cracks.csv" || fail "crack tables differ between 1 and 2 threads"

# Killed and resumed equals uninterrupted (curve, crack table, frame list, frames with their displacements).
ck=(--set specimen.width_mm=0.2 --set specimen.height_mm=0.4 --set specimen.growth_steps=2000 --set specimen.relax_steps=500
    --set loading.quasi_static_check=false --set loading.speed_m_per_s=0.1 --set output.frame_every_samples=20)
comp="$src/data/scenes/dem_compression.json"
"$bin" run "$comp" "${ck[@]}" --out "$work/c_full" --threads 1 >/dev/null 2>&1 || fail "uninterrupted compression"
expect_kill_resume_equal "$work/c_full" "$work/c_kill" \
  "curve.csv cracks.csv result.pvd $(cd "$work/c_full" && echo frame_*.vtp cracks_*.vtp)" \
  run "$comp" "${ck[@]}" --threads 1 --checkpoint-every 3
expect_input_error "DIR = $work/nowhere" resume "$work/nowhere"
expect_input_error "calibration.free = stiffness" run "$src/data/scenes/dem_calibrate.json" --set 'calibration.free=["stiffness"]' --out "$work/x"

# Calibration on a tiny specimen: logs every evaluation and installs the material in the data directory.
mkdir -p "$work/data" && cp -r "$src/data/materials" "$src/data/experiments" "$work/data/"
KERF_DATA_DIR="$work/data" "$bin" run "$src/data/scenes/dem_calibrate.json" --set specimen.width_mm=0.16 \
    --set specimen.height_mm=0.32 --set specimen.growth_steps=2000 --set specimen.relax_steps=500 \
    --set loading.speed_m_per_s=0.2 --set calibration.max_evaluations=2 --set calibration.tolerance_percent=99 \
    --set calibration.material_name=tiny_fj --set calibration.install_material=true --out "$work/cal" >"$work/cal.out" 2>&1 ||
  fail "calibration: $(cat "$work/cal.out")"
grep -q "^evaluation 0: " "$work/cal.out" || fail "no evaluation log line"
[ "$(wc -l < "$work/cal/calibration_log.csv")" -ge 2 ] || fail "calibration_log.csv"
cmp -s "$work/cal/tiny_fj.json" "$work/data/materials/tiny_fj.json" || fail "material not installed"
KERF_DATA_DIR="$work/data" "$bin" run "$scene" "${small[@]}" --set material.base=tiny_fj --out "$work/t3" >/dev/null 2>&1 ||
  fail "the installed material cannot be used as a base"
echo "dem_cli: ok"
