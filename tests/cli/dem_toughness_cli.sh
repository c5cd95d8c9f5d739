#!/usr/bin/env bash
# kerf-dem run of kind toughness (the notched beam in three-point bending, issue 37): bad input exits 2 naming the
# key (a notch longer than the beam is deep, a negative notch or roller, a beam shorter than its span 4 W,
# checkpoints); a small beam on two packings writes the summary's keys (K_IC with its standard error, G_c), the
# curve and the figures.
# Usage: dem_toughness_cli.sh <dir of built programs> <source dir>
source "$(dirname "$0")/lib/dem_common.sh" "$@"
scene="$src/data/scenes/dem_toughness.json"

expect_input_error "toughness.notch_depth_mm = 0.6: expected a notch shorter than the beam's depth" \
  run "$scene" --set toughness.notch_depth_mm=0.6 --out "$work/bad"
expect_input_error "toughness.notch_depth_mm = -0.1" run "$scene" --set toughness.notch_depth_mm=-0.1 --out "$work/bad"
expect_input_error "toughness.roller_radius_mm = -0.05" run "$scene" --set toughness.roller_radius_mm=-0.05 --out "$work/bad"
expect_input_error "specimen.width_mm = 1.5: expected a beam at least 2.1 mm long" \
  run "$scene" --set specimen.width_mm=1.5 --out "$work/bad"
expect_input_error "toughness.speed_m_per_s = -1" run "$scene" --set toughness.speed_m_per_s=-1 --out "$work/bad"
expect_input_error "--checkpoint-every" run "$scene" --checkpoint-every 10 --out "$work/bad"

# W = 0.2 mm, radii 10-13 um (8 disks deep), a/W = 0.4, two packings: seconds.
small=(--set specimen.width_mm=0.86 --set specimen.height_mm=0.2 --set specimen.growth_steps=2000
       --set specimen.relax_steps=500 --set toughness.notch_depth_mm=0.08 --set toughness.roller_radius_mm=0.03
       --set toughness.speed_m_per_s=0.05 --set toughness.quasi_static_check=false)
OMP_NUM_THREADS=1 "$bin" run "$scene" "${small[@]}" --replicates 2 --out "$work/small" >"$work/log" 2>&1 ||
  fail "small toughness run failed: $(tail -5 "$work/log")"
for f in summary.json curve.csv cracks.csv curve.png specimen.png crack.png; do
  [ -s "$work/small/$f" ] || fail "no $f"
done
python3 - "$work/small/summary.json" <<'PY' || fail "summary: see above"
import json, sys
r = json.load(open(sys.argv[1]))["results"]
for key in ["fracture_toughness_MPa_sqrt_m", "fracture_toughness_sem_MPa_sqrt_m", "fracture_energy_J_per_m2",
            "fracture_energy_sem_J_per_m2", "work_of_fracture_J_per_m2", "irwin_energy_J_per_m2"]:
    assert key in r, key
assert r["packings"] == 2 and len(r["per_packing"]) == 2
assert [p["seed"] for p in r["per_packing"]] == [1, 2]
ks = [p["fracture_toughness_MPa_sqrt_m"] for p in r["per_packing"]]
assert abs(r["fracture_toughness_MPa_sqrt_m"] - sum(ks) / 2) < 1e-12
assert abs(r["fracture_toughness_sem_MPa_sqrt_m"] - abs(ks[0] - ks[1]) / 2) < 1e-12  # s / sqrt(2) for two values
for p in r["per_packing"]:
    assert p["fracture_toughness_MPa_sqrt_m"] > 0 and p["fracture_energy_J_per_m2"] > 0, p
    assert p["fracture_energy_J_per_m2"] <= p["work_of_fracture_J_per_m2"] * (1 + 1e-9), p
PY
# The curve has both packings.
[ "$(cut -d, -f1 "$work/small/curve.csv" | sort -u | tr '\n' ' ')" = "1 2 seed " ] || fail "curve.csv: seeds $(cut -d, -f1 "$work/small/curve.csv" | sort -u)"
echo "dem_toughness_cli: ok"
