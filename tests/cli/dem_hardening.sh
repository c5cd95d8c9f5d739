#!/usr/bin/env bash
# Issue 24, kerf-dem: extreme values that pass validation end with exit 3 and one line (never an abort from an
# exception inside an OpenMP region); a deep value is refused while parsing; an unwritable --out is exit 4
# before any work; a run marks its directory while in progress, and a rerun removes the temporary files and
# the outputs of the run before; 40 single-bit flips of a real cut checkpoint each give exit 3.
source "$(dirname "$0")/lib/dem_common.sh" "$@"

one_error_line() {  # one_error_line <status wanted> <args...>
  local want=$1; shift
  "$bin" "$@" >"$work/out" 2>"$work/err"
  local rc=$?
  [ $rc -eq "$want" ] || fail "exit $rc (expected $want) for: $* ($(head -c 300 "$work/err"))"
  [ "$(wc -l <"$work/err")" -eq 1 ] && grep -q "^kerf-dem: error: " "$work/err" ||
    fail "not one 'kerf-dem: error:' line for: $*: $(head -c 300 "$work/err")"
}
tiny=(--set specimen.width_mm=0.2 --set specimen.height_mm=0.2 --threads 2)
for density in 1e308 1e-320 1e-300; do
  one_error_line 3 run "$src/data/scenes/dem_specimen.json" "${tiny[@]}" --set material.density_kg_per_m3=$density --out "$work/d"
  grep -q "material.density_kg_per_m3 = " "$work/err" || fail "density $density: the message names no input: $(cat "$work/err")"
done
one_error_line 3 run "$src/data/scenes/dem_tension.json" "${tiny[@]}" --set specimen.thickness_mm=1e-300 --out "$work/d"
[ ! -e "$work/d/kerf.running" ] || fail "a failed run left its in-progress marker"
# A time step made tiny by engine.time_step_safety: the message names that key, not the loading speed.
one_error_line 2 run "$src/data/scenes/dem_tension.json" "${tiny[@]}" --set engine.time_step_safety=1e-300 --out "$work/s"
grep -q "^kerf-dem: error: engine.time_step_safety = 1e-300: expected at least " "$work/err" ||
  fail "tiny time_step_safety: $(cat "$work/err")"
[ -z "$(find "$work/d" -name '*.tmp-*')" ] || fail "a failed run left temporary files"

# A deep value under the ignored "description" key: refused while parsing, before any work.
python3 -c "import sys; t=open(sys.argv[1]).read(); i=t.index('{') + 1; print(t[:i] + '\"description\": ' + '['*5000 + ']'*5000 + ',' + t[i:])" \
  "$src/data/scenes/dem_specimen.json" >"$work/deep.json"
one_error_line 2 run "$work/deep.json" --out "$work/deep"
grep -q "nested deeper than 64" "$work/err" || fail "deep description: $(cat "$work/err")"
one_error_line 2 run "$src/data/scenes" --out "$work/x"
grep -q "expected a JSON file, not a directory" "$work/err" || fail "directory as scene: $(cat "$work/err")"

# An unwritable output directory: exit 4 at once, not after the run.
start=$(date +%s)
one_error_line 4 run "$src/data/scenes/dem_tension.json" --out /proc/kerf-cannot-write
[ $(( $(date +%s) - start )) -lt 5 ] || fail "the unwritable --out was found late"
one_error_line 2 run "$src/data/scenes/dem_tension.json" --out ""

# The marker while in progress, and a rerun into the same directory: the stale temporary file of a killed run
# and the files of the run before are gone, the user's own file stays.
# The cut is long enough (about 10 times the wait for its first checkpoint, under the sanitizers too) to be
# still running when it is killed on a loaded machine.
small=(--set specimen.width_mm=0.4 --set specimen.height_mm=0.25 --set specimen.growth_steps=2000
       --set specimen.relax_steps=500 --set cut.depth_of_cut_mm=0.05 --set cut.length_mm=0.25
       --set output.frame_every_samples=500 --set cut.speed_m_per_s=2)
scene="$src/data/scenes/dem_cut.json"
"$bin" run "$scene" "${small[@]}" --threads 1 --checkpoint-every 40 --out "$work/k" >/dev/null 2>&1 &
pid=$!
kill_after_checkpoint $pid "$work/k"
[ -e "$work/k/kerf.running" ] || fail "a killed run left no in-progress marker"
cp "$work/k/checkpoint.bin" "$work/good.bin"
echo partial >"$work/k/forces.csv.tmp-0badc0de"
echo mine >"$work/k/notes.txt"
"$bin" run "$src/data/scenes/dem_specimen.json" --set specimen.width_mm=0.3 --set specimen.height_mm=0.2 --threads 1 \
  --out "$work/k" >/dev/null 2>"$work/err" || fail "rerun: $(cat "$work/err")"
[ ! -e "$work/k/forces.csv.tmp-0badc0de" ] || fail "the rerun left the killed run's temporary file"
[ ! -e "$work/k/checkpoint.bin" ] || fail "the rerun left the killed run's checkpoint"
[ ! -e "$work/k/kerf.running" ] || fail "the finished rerun left its in-progress marker"
[ -e "$work/k/notes.txt" ] || fail "the rerun removed a file it did not write"

# 40 single-bit flips of the real cut checkpoint: exit 3 every time, with a message, and nothing resumed.
size=$(stat -c %s "$work/good.bin")
for k in $(seq 40); do
  mkdir -p "$work/flip"
  python3 - "$work/good.bin" "$work/flip/checkpoint.bin" "$size" "$k" <<'PY'
import random, sys
data = bytearray(open(sys.argv[1], 'rb').read())
rng = random.Random(int(sys.argv[4]))
bit = rng.randrange(8 * int(sys.argv[3]))
data[bit // 8] ^= 1 << (bit % 8)
open(sys.argv[2], 'wb').write(data)
PY
  one_error_line 3 resume "$work/flip" --threads 1
  grep -q "damaged\|another kerf-dem version\|not a kerf-dem checkpoint" "$work/err" || fail "flip $k: $(cat "$work/err")"
  [ ! -e "$work/flip/summary.json" ] || fail "flip $k: a damaged checkpoint was resumed"
  rm -rf "$work/flip"
done
mkdir -p "$work/trail" && cp "$work/good.bin" "$work/trail/checkpoint.bin" && printf x >>"$work/trail/checkpoint.bin"
one_error_line 3 resume "$work/trail" --threads 1
echo "dem hardening: ok"
