#!/usr/bin/env bash
# kerf-dem's log when standard output is not a terminal (issue 23 item 6): a line every --log-every samples
# of each stage (step, time, travel, forces, cracks, particle-steps/s, percent, ETA), each stage ending at 100 %
# with its performance line, and the run's performance line at the end; --log-every 0: none; a bad value
# exits 2 naming the option.
# Usage: dem_log_cli.sh <dir of built programs> <source dir>
source "$(dirname "$0")/lib/dem_common.sh" "$@"

scene="$src/data/scenes/dem_cut.json"
small=(--set specimen.width_mm=0.4 --set specimen.height_mm=0.25 --set specimen.growth_steps=2000
       --set specimen.relax_steps=500 --set cut.depth_of_cut_mm=0.05 --set cut.length_mm=0.08
       --set output.frame_every_samples=0 --set cut.speed_m_per_s=2 --set cut.sample_every_steps=20)
expect_input_error "--log-every" run "$scene" "${small[@]}" --log-every -1 --out "$work/x"

"$bin" run "$scene" "${small[@]}" --log-every 10 --threads 1 --out "$work/c" >"$work/log" 2>"$work/err" ||
  fail "cut run: $(cat "$work/err")"
num='[-+0-9.e]+'
cut_line="^cut: step [0-9]+ time $num s travel $num mm cutting $num N thrust $num N cracks [0-9]+ \| $num particle-steps/s \| [0-9]+ %( \| ETA [0-9.]+ (s|min|h))?$"
n_cut=$(grep -cE "$cut_line" "$work/log")
# forces.csv has one row per sample: a line every 10 of them, and the last one.
n_samples=$(($(wc -l <"$work/c/forces.csv") - 1))
[ "$n_samples" -ge 20 ] || fail "only $n_samples samples: the test needs a longer cut"
[ "$n_cut" -eq $((n_samples / 10 + (n_samples % 10 != 0))) ] || fail "$n_cut cut lines for $n_samples samples: $(cat "$work/log")"
grep -E "^cut: step" "$work/log" | tail -1 | grep -qE "\| 100 %$" || fail "the cut's last line is not at 100 %: $(cat "$work/log")"
# The ETA (issue 55 item 6) as the terminal's bar has it: on the lines before a stage's last one.
grep -E "^cut: step" "$work/log" | head -n -1 | grep -qE " \| [0-9]+ % \| ETA [0-9.]+ (s|min|h)$" ||
  fail "no ETA in the cut's lines: $(grep -E '^cut: step' "$work/log" | head -3)"
# The last line carries the last sample of forces.csv: travel and forces as the CSV has them (to 4 digits).
last=$(tail -1 "$work/c/forces.csv")
travel=$(echo "$last" | awk -F, '{printf "%.4g", $1}')
main=$(echo "$last" | awk -F, '{printf "%.4g", $3}')
grep -E "^cut: step" "$work/log" | tail -1 | grep -qF "travel $travel mm cutting $main N" ||
  fail "the last cut line does not match forces.csv ($last): $(grep -E '^cut: step' "$work/log" | tail -1)"
# The genesis logs its steps; each stage ends with its performance line; the run with the LAMMPS-like one.
grep -qE "^specimen genesis: [0-9]+ of [0-9]+ steps \| $num steps/s \| [0-9]+ %( \| ETA [0-9.]+ (s|min|h))?$" "$work/log" || fail "no genesis line: $(cat "$work/log")"
grep -qE "^specimen genesis: step [0-9]+ .* \| 100 %$" "$work/log" || fail "the genesis does not end at 100 %"
grep -qE "^specimen genesis: done: [0-9]+ steps of [0-9]+ particles in $num s, $num particle-steps/s$" "$work/log" ||
  fail "no genesis performance line"
grep -qE "^cut: done: [0-9]+ steps of [0-9]+ particles in $num s, $num particle-steps/s$" "$work/log" || fail "no cut performance line"
grep -qE "^performance: $num s wall, 2 stages, [0-9]+ steps, $num particle-steps/s, 1 threads$" "$work/log" ||
  fail "no performance line: $(tail -3 "$work/log")"
tail -1 "$work/log" | grep -q "^performance:" || fail "the performance line is not the last"
grep -q "^cut: cutting force" "$work/log" || fail "the cut's result line is gone"

"$bin" run "$scene" "${small[@]}" --log-every 0 --threads 1 --out "$work/c0" >"$work/log0" 2>"$work/err" ||
  fail "cut run: $(cat "$work/err")"
! grep -qE "^(cut: step|cut: done|specimen genesis|performance)" "$work/log0" || fail "--log-every 0 still logs: $(cat "$work/log0")"
grep -q "^cut: cutting force" "$work/log0" || fail "--log-every 0 lost the result line"
# A resumed run logs too: kill a checkpointed cut, resume it with stdout to a file.
"$bin" run "$scene" "${small[@]}" --threads 1 --checkpoint-every 5 --out "$work/k" >/dev/null 2>&1 &
pid=$!
kill_after_checkpoint $pid "$work/k"
"$bin" resume "$work/k" --threads 1 --log-every 1 >"$work/logr" 2>"$work/err" || fail "resume: $(cat "$work/err")"
grep -qE "^cut: step [0-9]+ .* \| 100 %$" "$work/logr" || fail "the resumed cut does not log to 100 %: $(tail -3 "$work/logr")"
tail -1 "$work/logr" | grep -q "^performance:" || fail "the resumed run has no performance line"
echo "dem log: ok"
