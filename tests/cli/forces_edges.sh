#!/usr/bin/env bash
# kerf-forces at the edges of the analytic models (issue 22): every reproducer of the issue, with its exit status
# and message or value.
set -u
bin="$1/kerf-forces"; src="$2"; a2024="$src/data/scenes/a2024_planing.json"; steel="$src/data/scenes/aisi1045_oxley.json"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect() {  # expect STATUS PATTERN -- ARGS...  (PATTERN searched in stdout and stderr)
  local status=$1 pattern=$2; shift 3
  "$bin" "$@" >"$tmp/out" 2>"$tmp/err"; local got=$?
  if [ "$got" -ne "$status" ] || ! cat "$tmp/out" "$tmp/err" | grep -q -- "$pattern"; then
    fail "kerf-forces $* -> status $got (want $status, '$pattern'): $(tail -3 "$tmp/err")"
  fi
}
column() {  # column CSV NAME: the value of NAME in the first data row
  python3 -c "import csv,sys; print(next(csv.DictReader(open(sys.argv[1])))[sys.argv[2]])" "$1" "$2"
}

# 1. One friction angle: r = 0 with a measured chip ratio, Liu-Li and Merchant give the same forces and beta.
cut='cut={"uncut_chip_thickness_um": 3, "width_mm": 2, "speed_m_per_min": 10, "friction_angle_deg": 20, "chip_ratio": 0.5}'
for force in liu_li merchant; do
  "$bin" predict "$a2024" --set tool.edge_radius_um=0 --set models.shear_angle=chip_ratio --set "$cut" \
    --set models.force=$force --csv "$tmp/$force.csv" >"$tmp/out" 2>&1 || fail "reproducer 1 ($force) exits $?"
done
for name in cutting_force_N thrust_force_N friction_angle_deg; do
  [ "$(column "$tmp/liu_li.csv" $name)" = "$(column "$tmp/merchant.csv" $name)" ] || fail "reproducer 1: $name differs"
done
python3 -c "import sys; b=float(sys.argv[1]); sys.exit(0 if abs(b - 46.96) < 0.01 else 1)" \
  "$(column "$tmp/liu_li.csv" friction_angle_deg)" || fail "reproducer 1: beta is not the closure's 46.96 deg"

# 2. The stagnation cut-off on the whole tool: rake -60 deg cuts no chip; the force left is the ploughing force
#    under the edge (issue 38), zero with models.ploughing = none.
expect 0 "cutting force     0 N" -- predict "$a2024" --set models.shear_angle=merchant --set tool.rake_deg=-60 \
  --set cut.uncut_chip_thickness_um=3 --set models.ploughing=none
"$bin" predict "$a2024" --set models.shear_angle=merchant --set tool.rake_deg=-60 --set cut.uncut_chip_thickness_um=3 \
  --csv "$tmp/plough.csv" >/dev/null 2>&1 || fail "reproducer 2 with ploughing exits $?"
[ "$(column "$tmp/plough.csv" edge_cutting_force_N)" = 0 ] || fail "reproducer 2: a chip force under the cut-off"
[ "$(column "$tmp/plough.csv" cutting_force_N)" = "$(column "$tmp/plough.csv" ploughing_cutting_force_N)" ] &&
  python3 -c "import sys; sys.exit(0 if float(sys.argv[1]) > 0 else 1)" "$(column "$tmp/plough.csv" cutting_force_N)" ||
  fail "reproducer 2: the force is not the ploughing force alone"
expect 0 "guard             no_chip_on_rake_face" -- predict "$a2024" --set tool.rake_deg=-60

# 3. Extended Oxley: no physical solution is exit 3 naming why; Oxley's own beta is printed.
expect 3 "delta at its bound (0.2" -- predict "$a2024" --set models.force=oxley --set tool.edge_radius_um=0 \
  --set cut.uncut_chip_thickness_um=200
expect 3 "temperature at melting" -- predict "$steel" --set tool.rake_deg=-60
expect 0 "friction angle    .* deg (from the extended-Oxley solution)" -- predict "$steel" --set cut.friction_angle_deg=5
"$bin" sweep "$a2024" --set models.force=oxley --set tool.edge_radius_um=0 \
  --vary cut.uncut_chip_thickness_um=150:300:16 --csv "$tmp/sweep.csv" 2>"$tmp/err" || fail "the Oxley sweep exits $?"
grep -q "16 refused" "$tmp/err" || fail "the Oxley sweep: $(cat "$tmp/err")"

# 4. An inapplicable contact-length variant leaves its cell empty; the prediction goes on.
expect 0 "contact_length_altintas_mssp not applicable" -- predict "$a2024" --set tool.rake_deg=-60 --csv "$tmp/cl.csv"
[ -z "$(column "$tmp/cl.csv" contact_length_altintas_mssp_mm)" ] || fail "reproducer 4: the MSSP cell is not empty"
[ -n "$(column "$tmp/cl.csv" contact_length_altintas_mep_mm)" ] || fail "reproducer 4: the MEP cell is empty"

# 5. Plausibility.
expect 0 "no_chip_on_rake_face" -- predict "$a2024" --set tool.edge_radius_um=0 --set models.shear_angle=chip_ratio \
  --set "$cut" --set tool.rake_deg=-89.9
expect 2 "cut.chip_ratio = 3: expected a shear angle and friction closure giving a friction angle >= 0" -- \
  predict "$a2024" --set models.shear_angle=chip_ratio --set cut.chip_ratio=3 --set tool.rake_deg=0
expect 2 "cut.feed_rate_um_per_s = 1e+09: expected a feed per revolution below" -- \
  predict "$src/validation/k9_trepanning/scene.json" --set cut.feed_rate_um_per_s=1e9
"$bin" predict "$steel" --set models.force=merchant --set cut.friction_coefficient=0.3 \
  --set cut.uncut_chip_thickness_um=150 >"$tmp/out" 2>&1 || fail "steel merchant exits $?"
grep -q "validated up to h = 0.1 mm" "$tmp/out" && fail "the A2024 contact-length warning fires for AISI 1045"
expect 0 "validated up to h = 0.1 mm" -- predict "$a2024" --set cut.uncut_chip_thickness_um=150
psic='{"name": "psic_jc", "elastic": {"youngs_modulus_GPa": 410, "poissons_ratio": 0.14}, "johnson_cook": {"A_MPa": 8000, "B_MPa": 0, "n": 1, "C": 0, "m": 1, "reference_strain_rate_per_s": 1, "room_temperature_K": 293.15, "melting_temperature_K": 3003}, "microstructure": {"grain_size_um": 1, "burgers_vector_nm": 0.308, "misorientation_deg": 2.5}}'
given='models.deformation=given'
"$bin" predict "$src/data/scenes/psic_orthogonal.json" --set "material=$psic" --set "$given" --set cut.strain=1 \
  --set cut.strain_rate_per_s=1e6 --set cut.temperature_K=3002.9 --csv "$tmp/hot.csv" >/dev/null 2>&1 || fail "hot exits $?"
python3 -c "import sys; sys.exit(0 if float(sys.argv[1]) < 1e-3 else 1)" "$(column "$tmp/hot.csv" cutting_force_N)" \
  || fail "the force at 3002.9 K is not continuous with 0 N at melting: $(column "$tmp/hot.csv" cutting_force_N) N"

[ "$failures" -eq 0 ] && echo "all edge checks passed"
exit "$failures"
