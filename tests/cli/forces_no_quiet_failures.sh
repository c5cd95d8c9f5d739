#!/usr/bin/env bash
# kerf-forces fails loudly where it used to go on quietly (issue 40 item 5): a --vary key the scene does not read
# is exit 2 (not a CSV of refused points), while a value the scene refuses is still that point's error; compare
# refuses a CSV none of whose columns sets a condition unless --pool; `--csv -` puts only the CSV on standard
# output (predict, either scene kind, and sweep), the text going to standard error.
# Usage: forces_no_quiet_failures.sh <dir of built programs> <source dir>
source "$(dirname "$0")/lib/forces_common.sh" "$@"
fail() { echo "FAIL: $*"; exit 1; }
scene="$src/data/scenes/psic_orthogonal.json"
k9="$src/validation/k9_trepanning/scene.json"

# Unknown --vary keys: the key, the parser's did-you-mean, no CSV.
expect 2 "--vary = tool.edge_radius: expected a known key (did you mean 'edge_radius_um'?)" -- \
  sweep "$scene" --vary tool.edge_radius=0,1 --csv "$tmp/s.csv"
expect 2 "--vary = tools.rake_deg: expected a known key (did you mean 'tool'?)" -- \
  sweep "$scene" --vary tools.rake_deg=0,5 --csv "$tmp/s.csv"
expect 2 "--vary = cut.uncut_chip_thickness_nm: expected a known key" -- \
  sweep "$scene" --vary tool.rake_deg=0,5 --vary cut.uncut_chip_thickness_nm=10:100:3 --csv "$tmp/s.csv"
expect 2 "'material' is not an object" -- sweep "$scene" --vary material.density_kg_per_m3=1,2 --csv "$tmp/s.csv"
# The same for the other scene kind (one library sweep for every kind, issue 39).
expect 2 "--vary = cut.feed_rate_um_per_min: expected a known key (did you mean 'feed_rate_um_per_s'?)" -- \
  sweep "$k9" --vary cut.feed_rate_um_per_min=10,20 --csv "$tmp/s.csv"
[ ! -e "$tmp/s.csv" ] || fail "a sweep with an unknown key wrote its CSV"
# A known key whose first value the scene refuses: that point is refused, the sweep goes on (exit 0).
"$bin" sweep "$scene" --vary tool.rake_deg=95,0 --csv "$tmp/s.csv" 2>"$tmp/err" || fail "refused value: $(cat "$tmp/err")"
grep -q "2 points written to .* (1 refused" "$tmp/err" || fail "refused value: $(cat "$tmp/err")"

# compare: no column sets a condition. Refused, naming the columns that matched nothing and the way out.
printf 'depth_um,cutting_force_N\n0.1,1.5\n0.2,2.5\n' >"$tmp/nocond.csv"
expect 2 "none matched (unused: depth_um; --pool, in Python pool=True, takes every row" -- \
  compare "$scene" --experiments "$tmp/nocond.csv" --out "$tmp/r"
grep -qF "uncut_chip_thickness_um" "$tmp/err" || fail "compare's refusal does not name the scene's condition keys"
[ ! -e "$tmp/r/report.md" ] || fail "a refused compare wrote a report"
"$bin" compare "$scene" --experiments "$tmp/nocond.csv" --pool --out "$tmp/r" >"$tmp/out" 2>"$tmp/err" ||
  fail "compare --pool: $(cat "$tmp/err")"
python3 - "$tmp/r/summary.json" <<'PY' || fail "compare --pool did not take both rows at the scene's condition"
import json, sys
s = json.load(open(sys.argv[1]))
assert s["quantities"]["cutting_force"]["n"] == 1, s["quantities"]["cutting_force"]  # one condition, two replicates
PY
# A matched condition needs no flag.
printf 'uncut_chip_thickness_um,cutting_force_N\n0.1,1.5\n0.2,2.5\n' >"$tmp/cond.csv"
"$bin" compare "$scene" --experiments "$tmp/cond.csv" --out "$tmp/c" >/dev/null 2>"$tmp/err" ||
  fail "compare with a condition column: $(cat "$tmp/err")"

# --csv -: standard output is the CSV alone (what predict --csv FILE writes), the text is on standard error.
for s in "$scene" "$k9"; do
  "$bin" predict "$s" --csv "$tmp/file.csv" >"$tmp/text" 2>/dev/null || fail "predict $s --csv FILE"
  "$bin" predict "$s" --csv - >"$tmp/stdout.csv" 2>"$tmp/err" || fail "predict $s --csv -: $(cat "$tmp/err")"
  cmp -s "$tmp/file.csv" "$tmp/stdout.csv" || fail "predict $s --csv -: standard output is not the CSV: $(head -3 "$tmp/stdout.csv")"
  cmp -s "$tmp/text" "$tmp/err" || fail "predict $s --csv -: standard error is not the text predict prints"
  grep -q "^scene " "$tmp/err" || fail "predict $s --csv -: no text on standard error"
done
"$bin" sweep "$scene" --vary tool.rake_deg=0,5,10 --csv "$tmp/sweep.csv" 2>/dev/null || fail "sweep --csv FILE"
"$bin" sweep "$scene" --vary tool.rake_deg=0,5,10 --csv - >"$tmp/sweep_stdout.csv" 2>"$tmp/err" || fail "sweep --csv -"
cmp -s "$tmp/sweep.csv" "$tmp/sweep_stdout.csv" || fail "sweep --csv -: standard output is not the CSV"
grep -q "3 points written to -" "$tmp/err" || fail "sweep --csv -: the summary line is not on standard error"

[ "$failures" -eq 0 ] || exit 1
echo "forces_no_quiet_failures: ok"
