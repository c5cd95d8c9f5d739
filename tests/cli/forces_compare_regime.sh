#!/usr/bin/env bash
# kerf-forces compare, regime and trepanning scenes through predict and sweep.
set -u
bin="$1/kerf-forces"; src="$2"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
k9="$src/validation/k9_trepanning/scene.json"; csv="$src/data/experiments/k9_trepanning.csv"
maps=(--map cut.feed_rate_um_per_s=feed_rate_um_s --map axial_force_N=axial_force_test_N --map torque_N_m=torque_test_Nm)

"$bin" compare "$k9" --experiments "$csv" "${maps[@]}" --fit --out "$tmp/k9" >"$tmp/out" || fail "compare --fit failed"
for f in report.md comparison.csv summary.json parity_axial_force.png parity_torque.png; do
  [ -s "$tmp/k9/$f" ] || fail "compare wrote no $f"
done
python3 - "$tmp/k9/summary.json" <<'PY' || exit 1
import json, sys
s = json.load(open(sys.argv[1]))
q = s["quantities"]
for key, band in (("axial_force", 5.0), ("torque", 6.7)):
    for field in ("n", "mean_abs_error_percent", "max_abs_error_percent", "bias_percent"):
        assert field in q[key], (key, field)
    assert q[key]["n"] == 8
    assert q[key]["mean_abs_error_percent"] <= band, (key, q[key]["mean_abs_error_percent"])  # Yu et al. 2023's own figures
assert s["extra"]["fit"]["axial_force"]["loo_mean_abs_error_percent"] > q["axial_force"]["mean_abs_error_percent"]
print("compare checks passed")
PY
"$bin" compare "$k9" --experiments "$csv" --fit --out "$tmp/x" 2>"$tmp/err"; [ $? -eq 2 ] || fail "compare without matching columns must exit 2"
grep -q "axial_force_N" "$tmp/err" || fail "the error must name the expected columns"

"$bin" predict "$k9" --csv "$tmp/k9.csv" >/dev/null || fail "trepanning predict failed"
grep -q "axial_force_N" "$tmp/k9.csv" || fail "trepanning CSV lacks axial_force_N"
"$bin" sweep "$k9" --vary cut.feed_rate_um_per_s=10:20:11 --csv "$tmp/k9sweep.csv" 2>/dev/null || fail "trepanning sweep failed"
python3 - "$tmp/k9sweep.csv" <<'PY' || exit 1
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 11
ratio = [float(r["axial_force_N"]) / float(r["cut.feed_rate_um_per_s"]) for r in rows]
assert max(ratio) - min(ratio) < 1e-9 * max(ratio), "axial force must be linear in the feed rate (Eq. 21)"
print("trepanning sweep checks passed")
PY

"$bin" predict "$k9" --set 'models.trepanning.grits={"grit_density_per_mm2": 20, "grit_width_um": 50}' \
  --csv "$tmp/grits.csv" >/dev/null || fail "trepanning predict with grits failed"
python3 - "$tmp/grits.csv" <<'PY' || exit 1
import csv, sys
r = next(csv.DictReader(open(sys.argv[1])))
# Eqs. 1-20 sum back to the totals: N_c F_an = F_n.
assert abs(float(r["grit_count"]) * float(r["grit_normal_force_N"]) / float(r["axial_force_N"]) - 1) < 1e-9, r
assert r["grit_regime"] in ("ductile", "transition", "brittle") and float(r["critical_depth_nm"]) > 0
print("grit diagnostics checks passed")
PY
"$bin" regime "$src/data/scenes/psic_orthogonal.json" >"$tmp/regime" || fail "regime failed"
grep -q "critical depth" "$tmp/regime" && grep -q "regime  *transition" "$tmp/regime" || fail "regime output: $(cat "$tmp/regime")"
"$bin" regime "$src/data/scenes/psic_orthogonal.json" --set cut.uncut_chip_thickness_um=0.01 | grep -q "regime  *ductile" || fail "10 nm p-SiC must be ductile"
"$bin" regime "$src/data/scenes/a2024_planing.json" 2>"$tmp/err"; [ $? -eq 2 ] || fail "regime of a metal must be an input error"
grep -q "material.brittle" "$tmp/err" || fail "the regime error must name the missing group: $(cat "$tmp/err")"
"$bin" predict "$src/data/scenes/psic_orthogonal.json" --set cut.uncut_chip_thickness_um=1 --csv "$tmp/b.csv" | grep -q "brittle regime" || fail "no brittle warning"
grep -q ",brittle," "$tmp/b.csv" || fail "the CSV regime column must say brittle"
"$bin" report "$src/data/comparisons/soda_lime_dem_vs_experiment.json" --out "$tmp/soda" >/dev/null || fail "report failed"
python3 - "$tmp/soda/summary.json" <<'PY' || exit 1
import json, sys
q = json.load(open(sys.argv[1]))["quantities"]
# Yang et al. 2018: the paper's DEM (1 mm) against experiments (25.4 mm); both views must be reported.
assert {"main_force", "main_force_per_width", "thrust_force", "thrust_force_per_width"} <= set(q), q.keys()
print("report checks passed")
PY
echo "all compare/regime checks passed"
