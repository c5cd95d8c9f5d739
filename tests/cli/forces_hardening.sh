#!/usr/bin/env bash
# Issue 24, kerf-forces: each hostile input of the issue gives its exit status (2 input, 3 model or non-finite
# result, 4 output), one line on stderr with the program's prefix naming the key, and no file left behind.
source "$(dirname "$0")/lib/forces_common.sh" "$@"
scenes="$src/data/scenes"; trep="$src/validation/k9_trepanning/scene.json"
python3 -c "print('['*100000+']'*100000)" >"$tmp/deep.json"
expect 2 "nested deeper than 64" -- predict "$tmp/deep.json"
sed 's/"rake_deg": *[-0-9.]*/"rake_deg": 1e999/' "$scenes/psic_orthogonal.json" >"$tmp/overflow.json"
expect 2 "tool.rake_deg = 1e999: expected a finite number" -- predict "$tmp/overflow.json"
printf '{"material": "ps\\u0000ic\\nx\\u001b[31m"}' >"$tmp/control.json"
expect 2 'material = ps\x00ic\nx\x1b[31m: expected one of' -- predict "$tmp/control.json"
expect 2 "data/scenes: expected a JSON file, not a directory" -- predict "$scenes"
expect 3 "cutting_force_N is inf for cut.uncut_chip_thickness_um = 100, cut.width_mm = 1e+308" -- \
  predict "$scenes/a2024_planing.json" --set cut.width_mm=1e308
expect 2 "cut.width_mm = 9.88131e-323: expected a value in mm that stays a finite, non-zero number in SI" -- \
  predict "$scenes/psic_orthogonal.json" --set cut.width_mm=1e-322
expect 3 "is inf for cut.uncut_chip_thickness_um = 1e+308" -- \
  predict "$scenes/psic_orthogonal.json" --set cut.uncut_chip_thickness_um=1e308
expect 2 "cut.uncut_chip_thickness_um = 4.94066e-324: expected a value in um that stays" -- \
  predict "$scenes/psic_orthogonal.json" --set cut.uncut_chip_thickness_um=5e-324
expect 2 "cut.feed_rate_um_per_s = 1e+308" -- predict "$trep" --set cut.feed_rate_um_per_s=1e308
# (read through the field table, the speed is refused where it becomes subnormal in rev/s, before the feed check)
expect 2 "cut.spindle_speed_rpm = 9.99989e-321: expected a value in rev/min that stays a finite, non-zero number in SI" -- \
  predict "$trep" --set cut.spindle_speed_rpm=1e-320
expect 2 "--vary = tool.rake_deg=nan:2:3: expected finite START and STOP" -- \
  sweep "$scenes/psic_orthogonal.json" --vary tool.rake_deg=nan:2:3 --csv "$tmp/s.csv"
expect 2 "--vary = tool.rake_deg=0:inf:3: expected finite START and STOP" -- \
  sweep "$scenes/psic_orthogonal.json" --vary tool.rake_deg=0:inf:3 --csv "$tmp/s.csv"
expect 2 "--threads" -- sweep "$scenes/psic_orthogonal.json" --threads x --vary tool.rake_deg=0:1:2 --csv "$tmp/s.csv"
expect 2 '--csv = "": expected a file name' -- predict "$scenes/psic_orthogonal.json" --csv ""
# An output that cannot be written: status 4, found before the sweep runs.
expect 4 "cannot write '/proc/kerf-cannot-write'" -- \
  sweep "$scenes/psic_orthogonal.json" --vary tool.rake_deg=0:1:2 --csv /proc/kerf-cannot-write/x.csv
[ -z "$(ls "$tmp" | grep -v -e '^deep.json$' -e '^overflow.json$' -e '^control.json$' -e '^out$' -e '^err$')" ] ||
  { echo "FAIL: files left behind: $(ls "$tmp")"; failures=$((failures + 1)); }
# Special files are written through: a FIFO stays a FIFO and its reader gets the row; a link stays a link.
mkfifo "$tmp/pipe"
(cat "$tmp/pipe" >"$tmp/from_pipe") &
"$bin" predict "$scenes/psic_orthogonal.json" --csv "$tmp/pipe" >/dev/null 2>&1 || { echo "FAIL: --csv FIFO"; failures=$((failures + 1)); }
wait
[ -p "$tmp/pipe" ] && grep -q "^force_model," "$tmp/from_pipe" || { echo "FAIL: the FIFO was replaced or not read"; failures=$((failures + 1)); }
ln -s target.csv "$tmp/link.csv"
"$bin" predict "$scenes/psic_orthogonal.json" --csv "$tmp/link.csv" >/dev/null 2>&1
[ -L "$tmp/link.csv" ] && [ -s "$tmp/target.csv" ] || { echo "FAIL: the link was replaced"; failures=$((failures + 1)); }
"$bin" predict "$scenes/psic_orthogonal.json" --csv - >"$tmp/stdout.csv" 2>/dev/null
grep -q "^force_model," "$tmp/stdout.csv" && [ ! -e ./- ] || { echo "FAIL: --csv - is not stdout"; failures=$((failures + 1)); }
[ "$failures" -eq 0 ] && echo "all hardening checks passed"
exit "$failures"
