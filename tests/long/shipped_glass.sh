#!/usr/bin/env bash
# The shipped glasses, pinned (issue 20 items 4 and 5): the bundled tension and compression scenes of the seed
# specimen (data/scenes/dem_tension.json, dem_compression.json) with each calibrated glass shipped, as it was
# calibrated, must meet Yang et al. 2018's Table 2 (data/experiments/soda_lime_properties.csv, row soda_lime_glass): E, nu
# (compression), sigma_t (tension), sigma_c (compression), each within 3 %, the calibration's tolerance:
#   - soda_lime_glass_fj: local damping 0.7, the scenes' 0.05 m/s and radii 7.5-10 um, packing seed 1;
#   - soda_lime_glass_fj_undamped: no damping, 0.025 m/s, radii 7.5-10 um, seed 1;
#   - soda_lime_glass_fj_undamped_cut: no damping, 0.025 m/s, the steady cut's radii 10-13 um, the mean of the
#     packings of seeds 1-3 (it was calibrated over those three: calibration.packings = 3);
#   - soda_lime_glass_sfj_cut: the same, a softening flat joint calibrated on a fifth target too
#     (data/scenes/dem_calibrate_toughness.json), so also its K_IC on the bundled toughness beam (damping 0.05,
#     0.02 m/s, packings seeds 1-3, as calibrated) within 10 % of soda-lime glass's 0.77 MPa sqrt(m)
#     (data/experiments/soda_lime_fracture.csv);
#   - soda_lime_glass_sfj_undamped_cut: the same five targets with the beam undamped at 0.01 m/s, the state the steady
#     cut uses its glass in (issue 54 item 1), so its K_IC on that beam within 10 % of 0.77 too;
#   - soda_lime_glass_sfj_weibull6_cut: the same, with Weibull joint strengths (m = 6) drawn at the genesis (issue 54
#     item 3);
#   - soda_lime_glass_flawed_cut: the same as the steady cut's glass, with seeded flaws (200 um, one per mm^2;
#     data/scenes/dem_calibrate_flawed.json).
# The scenes run as shipped but without their half-speed rerun (a check of the loading speed, not of the
# targets) and without frames. Minutes (about 12 runs); labelled "long", left out of the sanitized suite.
# Usage: shipped_glass.sh <dir of built programs> <source dir>
source "$(dirname "$0")/../cli/lib/dem_common.sh" "$@"

# glass:loading speed (m/s):radius_min_um:radius_max_um:packings
for entry in soda_lime_glass_fj:0.05:7.5:10:1 soda_lime_glass_fj_undamped:0.025:7.5:10:1 \
             soda_lime_glass_fj_undamped_cut:0.025:10:13:3 soda_lime_glass_sfj_cut:0.025:10:13:3 \
             soda_lime_glass_sfj_undamped_cut:0.025:10:13:3 soda_lime_glass_sfj_weibull6_cut:0.025:10:13:3 \
             soda_lime_glass_flawed_cut:0.025:10:13:3; do
  IFS=: read -r glass speed rmin rmax packings <<<"$entry"
  echo "$glass (loading $speed m/s, radii $rmin-$rmax um, $packings packing(s)):"
  for seed in $(seq 1 "$packings"); do
    for test in tension compression; do
      "$bin" run "$src/data/scenes/dem_$test.json" --set loading.quasi_static_check=false \
        --set output.frame_every_samples=0 --set material.base="$glass" --set loading.speed_m_per_s="$speed" \
        --set specimen.radius_min_um="$rmin" --set specimen.radius_max_um="$rmax" --set specimen.seed="$seed" \
        --threads "${KERF_LONG_THREADS:-1}" --out "$work/$glass/$seed/$test" \
        >"$work/$glass.$seed.$test.out" 2>&1 || fail "$glass seed $seed $test: $(tail -5 "$work/$glass.$seed.$test.out")"
    done
  done
  python3 - "$src/data/experiments/soda_lime_properties.csv" "$work/$glass" "$packings" <<'PY' || fail "$glass misses Table 2 (above)"
import csv, json, sys
rows = [r for r in csv.DictReader(line for line in open(sys.argv[1]) if not line.startswith("#"))]
target = next(r for r in rows if r["source"] == "soda_lime_glass")
n = int(sys.argv[3])
got = {"youngs_modulus_GPa": 0.0, "poissons_ratio": 0.0, "tensile_strength_MPa": 0.0, "compressive_strength_MPa": 0.0}
for seed in range(1, n + 1):
    tension = json.load(open(f"{sys.argv[2]}/{seed}/tension/summary.json"))["results"]
    compression = json.load(open(f"{sys.argv[2]}/{seed}/compression/summary.json"))["results"]
    got["youngs_modulus_GPa"] += compression["youngs_modulus_GPa"] / n
    got["poissons_ratio"] += compression["poissons_ratio"] / n
    got["tensile_strength_MPa"] += tension["tensile_strength_MPa"] / n
    got["compressive_strength_MPa"] += compression["compressive_strength_MPa"] / n
bad = 0
for key, value in got.items():
    error = value / float(target[key]) - 1
    print(f"{key}: {value:.4g} against {target[key]} ({100 * error:+.2f} %)")
    bad += abs(error) > 0.03
sys.exit(1 if bad else 0)
PY
done
# The five-target glasses' toughness, each as calibrated (the calibration's beam: stopped once the load has halved):
# glass:local damping on the beam:speed (m/s)
for entry in soda_lime_glass_sfj_cut:0.05:0.02 soda_lime_glass_sfj_undamped_cut:0:0.01 \
             soda_lime_glass_sfj_weibull6_cut:0:0.01; do
  IFS=: read -r glass damping speed <<<"$entry"
  "$bin" run "$src/data/scenes/dem_toughness.json" --set material.base="$glass" --set material.local_damping="$damping" \
    --set toughness.speed_m_per_s="$speed" --set toughness.stop_fraction_of_peak=0.5 \
    --set toughness.quasi_static_check=false --replicates 3 --threads "${KERF_LONG_THREADS:-1}" \
    --out "$work/$glass/toughness" >"$work/$glass.toughness.out" 2>&1 ||
    fail "$glass toughness: $(tail -5 "$work/$glass.toughness.out")"
  python3 - "$src/data/experiments/soda_lime_fracture.csv" "$work/$glass/toughness/summary.json" <<'PY' ||
import csv, json, sys
rows = [r for r in csv.DictReader(line for line in open(sys.argv[1]) if not line.startswith("#"))]
target = float(next(r for r in rows if r["quantity"] == "fracture_toughness_mode_I")["value"])
got = json.load(open(sys.argv[2]))["results"]["fracture_toughness_MPa_sqrt_m"]
print(f"fracture_toughness_MPa_sqrt_m: {got:.4g} against {target} ({100 * (got / target - 1):+.2f} %)")
sys.exit(1 if abs(got / target - 1) > 0.10 else 0)
PY
    fail "$glass misses K_IC"
done
echo "shipped_glass: ok"
