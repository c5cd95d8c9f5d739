#!/usr/bin/env bash
# kerf-forces compare on a spreadsheet's CSV (issue 23): a byte-order mark, CRLF line ends and quoted fields;
# the columns it did not use; a column in nm mapped to a key in um (converted) or in N (refused); regime and
# guards per row; the data set named by its file. Also --version, --vary lists and the inputs in predict's CSV.
set -u
bin="$1/kerf-forces"; src="$2"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
scene="$src/data/scenes/psic_orthogonal.json"

# Excel's "CSV UTF-8": BOM, CRLF, quoted header and text fields; depths in nm; one misspelt condition column.
printf '\xEF\xBB\xBF"uncut_chip_thickness_nm",cutting_force_N,"operator, shift",spead_m_per_min\r\n' >"$tmp/x.csv"
printf '50,0.9,"A, early",60\r\n100,1.6,"B, late",60\r\n100,1.8,"A, early",60\r\n200,3.1,B,60\r\n' >>"$tmp/x.csv"
"$bin" compare "$scene" --experiments "$tmp/x.csv" --map cut.uncut_chip_thickness_um=uncut_chip_thickness_nm \
  --out "$tmp/r" >"$tmp/out" 2>"$tmp/err" || { cat "$tmp/err"; fail "compare of a spreadsheet CSV failed"; }
grep -q "unused columns    operator, shift, spead_m_per_min" "$tmp/out" || { cat "$tmp/out"; fail "unused columns not listed"; }
grep -q "converted from nm to um" "$tmp/r/report.md" || fail "the nm column's conversion is not in the report"
grep -q "Measured: x.csv" "$tmp/r/report.md" || fail "the measured data set is not named by its file"
grep -q "Measured: measured" "$tmp/r/report.md" && fail "the report still says 'Measured: measured'"
grep -q "## Regime and guards per row" "$tmp/r/report.md" || fail "no regime and guards per row"
python3 - "$tmp/r/summary.json" "$tmp/r/comparison.csv" <<'PY' || exit 1
import csv, json, sys
s = json.load(open(sys.argv[1]))
assert s["quantities"]["cutting_force"]["n"] == 3, s["quantities"]["cutting_force"]["n"]  # 50, 100 (x2), 200 nm
rows = list(csv.DictReader(open(sys.argv[2])))
assert any(abs(float(r[k]) - 0.1) < 1e-12 for r in rows for k in r if k.startswith("uncut_chip_thickness")), rows[0]
PY
# The predicted force at the 100 nm row is predict's at 0.1 um.
"$bin" predict "$scene" --set cut.uncut_chip_thickness_um=0.1 --csv "$tmp/p.csv" >/dev/null || fail "predict failed"

# A column whose unit is of another kind is refused, naming the mapping.
"$bin" compare "$scene" --experiments "$tmp/x.csv" --map cut.uncut_chip_thickness_um=cutting_force_N --out "$tmp/y" \
  2>"$tmp/err"; [ $? -eq 2 ] || fail "a force column mapped to a length key must exit 2"
grep -q "cut.uncut_chip_thickness_um=cutting_force_N: expected a CSV column in a unit of length" "$tmp/err" || {
  cat "$tmp/err"; fail "the unit mismatch message"; }

# A ploughed cut: the guard shows per row on the terminal and in the report.
printf 'uncut_chip_thickness_um,cutting_force_N\n0.001,0.1\n0.1,1.6\n' >"$tmp/g.csv"
"$bin" compare "$scene" --experiments "$tmp/g.csv" --out "$tmp/g" >"$tmp/out" || fail "compare with a guard failed"
grep -q "^line 2 .*guards no_chip_on_edge" "$tmp/out" || { cat "$tmp/out"; fail "the guard of line 2 is not printed"; }

# --version names the version and the commit.
"$bin" --version >"$tmp/v" || fail "--version failed"
grep -Eq '^kerf-forces [0-9]+\.[0-9]+\.[0-9]+' "$tmp/v" || { cat "$tmp/v"; fail "--version line"; }

# --vary lists, and grids without float noise.
"$bin" sweep "$scene" --vary tool.rake_deg=-5,0,5 --vary cut.uncut_chip_thickness_um=0.01:0.1:10 --csv "$tmp/s.csv" \
  2>/dev/null || fail "sweep with a list failed"
[ "$(wc -l <"$tmp/s.csv")" -eq 31 ] || fail "3 x 10 points expected"
grep -q "^-5,0.05," "$tmp/s.csv" || fail "the grid value 0.05 is not printed as 0.05"
grep -q "0.049999999" "$tmp/s.csv" && fail "float noise in the grid"
"$bin" sweep "$scene" --vary tool.rake_deg=0,x --csv "$tmp/s.csv" 2>"$tmp/err"; [ $? -eq 2 ] || fail "a bad list must exit 2"

# predict's CSV carries its inputs.
head -1 "$tmp/p.csv" | grep -q "material,rake_deg,edge_radius_um,clearance_deg,speed_m_per_min" || fail "inputs in the CSV"
sed -n 2p "$tmp/p.csv" | grep -q ",psic,0,0.2,7,60," || { cat "$tmp/p.csv"; fail "input values in the CSV"; }
echo "spreadsheet checks passed"
