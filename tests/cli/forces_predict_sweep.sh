#!/usr/bin/env bash
# kerf-forces predict and sweep: the CSV has unit-carrying columns, one row per grid point, no NaN, and the
# physics holds across the sweep (force rises with thickness; per-width columns are force / width).
set -u
bin="$1/kerf-forces"; src="$2"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$bin" predict "$src/data/scenes/a2024_planing.json" --csv "$tmp/one.csv" >"$tmp/out" || fail "predict failed"
grep -q "cutting force" "$tmp/out" || fail "no cutting force printed"
head -1 "$tmp/one.csv" | tr ',' '\n' >"$tmp/cols"
for col in cutting_force_N thrust_force_N shear_angle_deg cutting_force_N_per_mm thrust_force_N_per_mm \
           contact_length_lee_shaffer_mep_mm contact_length_altintas_mssp_mm ploughed_thickness_um guards warnings; do
  grep -qx "$col" "$tmp/cols" || fail "column $col missing"
done
[ "$(wc -l <"$tmp/one.csv")" -eq 2 ] || fail "predict CSV must have a header and one row"

"$bin" sweep "$src/data/scenes/psic_orthogonal.json" --vary cut.uncut_chip_thickness_um=0.001:10:40:log \
  --vary tool.edge_radius_um=0:1:5 --csv "$tmp/sweep.csv" 2>/dev/null || fail "sweep failed"
[ "$(wc -l <"$tmp/sweep.csv")" -eq 201 ] || fail "sweep must write 200 rows"
grep -qi nan "$tmp/sweep.csv" && fail "NaN in sweep"
python3 - "$tmp/sweep.csv" <<'PY' || exit 1
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
by_radius = {}
for r in rows:
    assert r["error"] == "", r["error"]
    f, w = float(r["cutting_force_N"]), float(r["width_mm"])
    assert abs(float(r["cutting_force_N_per_mm"]) - f / w) <= 1e-9 * max(1.0, f), r
    by_radius.setdefault(r["tool.edge_radius_um"], []).append((float(r["cut.uncut_chip_thickness_um"]), f))
for radius, points in by_radius.items():
    points.sort()
    for (t1, f1), (t2, f2) in zip(points, points[1:]):
        assert f2 >= f1, f"force falls with thickness at r={radius}: {t1}->{t2}: {f1}->{f2}"
print("sweep checks passed")
PY

# --plot: the sweep's figure, a PNG with a PDF beside it, written whole; a sweep with nothing to plot is an
# input error naming --plot.
"$bin" sweep "$src/data/scenes/psic_orthogonal.json" --vary cut.uncut_chip_thickness_um=0.05:1.5:6 \
  --vary tool.edge_radius_um=0,1 --csv "$tmp/p.csv" --plot "$tmp/p.png" 2>/dev/null || fail "sweep --plot failed"
[ "$(head -c 8 "$tmp/p.png" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || fail "--plot wrote no PNG"
[ "$(head -c 5 "$tmp/p.pdf")" = "%PDF-" ] || fail "--plot wrote no PDF beside the PNG"
ls "$tmp" | grep -q "tmp" && fail "a temporary file was left: $(ls "$tmp")"
echo "sweep plot checks passed"
