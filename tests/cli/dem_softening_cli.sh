#!/usr/bin/env bash
# The softening flat joint from the command line (issue 37): a negative fracture energy exits 2 naming the key; with
# zero fracture energy a tension test's curve and cracks are the flat joint's byte for byte; with a fracture energy,
# killed after a checkpoint (elements softening, their damage in it) and resumed, it equals the uninterrupted run.
# Usage: dem_softening_cli.sh <dir of built programs> <source dir>
source "$(dirname "$0")/lib/dem_common.sh" "$@"
scene="$src/data/scenes/dem_tension.json"

expect_input_error "material.fracture_energy_J_per_m2 = -1: expected a non-negative value in J/m^2" \
  run "$scene" --set material.bond_model=softening_flat_joint --set material.fracture_energy_J_per_m2=-1 --out "$work/bad"
expect_input_error "material.fracture_energy_J_per_m2 = 1: expected a known key" \
  run "$scene" --set material.fracture_energy_J_per_m2=1 --out "$work/bad"

# A small specimen of a glass that breaks in tension (c about 5 sigma_c, as the calibrated glasses).
small=(--set specimen.width_mm=0.2 --set specimen.height_mm=0.4 --set specimen.growth_steps=2000
       --set specimen.relax_steps=500 --set loading.quasi_static_check=false --set loading.speed_m_per_s=0.1
       --set material.tensile_strength_MPa=85 --set material.cohesion_MPa=450 --set output.frame_every_samples=0)
"$bin" run "$scene" "${small[@]}" --threads 1 --out "$work/flat" >/dev/null 2>"$work/err" || fail "flat joint: $(cat "$work/err")"
"$bin" run "$scene" "${small[@]}" --set material.bond_model=softening_flat_joint --threads 1 --out "$work/soft0" \
  >/dev/null 2>"$work/err" || fail "softening, G_f = 0: $(cat "$work/err")"
for f in curve.csv cracks.csv; do
  cmp -s "$work/flat/$f" "$work/soft0/$f" || fail "$f of the softening joint with zero fracture energy differs from the flat joint's"
done
[ "$(wc -l <"$work/flat/cracks.csv")" -gt 5 ] || fail "the flat joint's test broke too few elements to compare"
grep -q '"bond_model": "softening_flat_joint"' "$work/soft0/summary.json" || fail "the summary does not name the law"

soft=("${small[@]}" --set material.bond_model=softening_flat_joint --set material.fracture_energy_J_per_m2=2)
"$bin" run "$scene" "${soft[@]}" --threads 1 --out "$work/full" >/dev/null 2>"$work/err" || fail "softening: $(cat "$work/err")"
cmp -s "$work/flat/curve.csv" "$work/full/curve.csv" && fail "a fracture energy of 2 J/m^2 changed nothing"
expect_kill_resume_equal "$work/full" "$work/kill" "curve.csv cracks.csv" run "$scene" "${soft[@]}" --threads 1 \
  --checkpoint-every 3
echo "dem_softening_cli: ok"
