#!/usr/bin/env bash
# kerf-dem resume keeps the run's provenance and counts its rates from the resume (issue 40 item 6): a cut
# interrupted by SIGTERM after its first checkpoint says how to continue it (one line, exit 143 as before), one
# interrupted before any checkpoint says there is none; the resumed summary's provenance is the original run's
# (command line, scene path and hash, overrides) with the resume appended (date, command line, sample); the
# resumed log starts at the checkpoint's step and its rates and performance count only the steps since.
# Usage: dem_resume_cli.sh <dir of built programs> <source dir>
source "$(dirname "$0")/lib/dem_common.sh" "$@"

scene="$src/data/scenes/dem_cut.json"
# A cut long enough that the run is still going when the signals below reach it, even on a loaded machine: 0.3 mm,
# 166,520 steps, 1.3 s on an idle core, the first checkpoint at step 500 (at 0.08 mm, 0.35 s, it once finished
# first while two other heavy jobs ran, 2026-12-06).
small=(--set specimen.width_mm=0.4 --set specimen.height_mm=0.25 --set specimen.growth_steps=2000
       --set specimen.relax_steps=500 --set cut.depth_of_cut_mm=0.05 --set cut.length_mm=0.3
       --set output.frame_every_samples=0 --set cut.speed_m_per_s=2 --set cut.sample_every_steps=20)

# SIGTERM after the first checkpoint (sample 25, step 500: late enough for the rate check below): the hint, and the
# signal's exit status.
"$bin" run "$scene" "${small[@]}" --threads 1 --checkpoint-every 25 --out "$work/k" >/dev/null 2>"$work/kerr" &
kill_after_checkpoint $! "$work/k" TERM
[ "$killed_status" -eq 143 ] || fail "SIGTERM: exit $killed_status (expected 143)"
[ ! -e "$work/k/summary.json" ] || fail "the run had finished before it was interrupted"
hint="kerf-dem: interrupted; continue with: kerf-dem resume $work/k"
[ "$(grep -c "interrupted" "$work/kerr")" -eq 1 ] && grep -qxF "$hint" "$work/kerr" ||
  fail "no single line '$hint' on stderr: $(cat "$work/kerr")"
# Interrupted before any checkpoint (none asked for): no resume to offer.
"$bin" run "$scene" "${small[@]}" --threads 1 --out "$work/n" >/dev/null 2>"$work/nerr" &
pid=$!
until [ -e "$work/n/kerf.running" ] || ! kill -0 $pid 2>/dev/null; do sleep 0.01; done
kill -TERM $pid 2>/dev/null || fail "the run without checkpoints ended before it could be interrupted"
wait $pid; status=$?
[ "$status" -eq 143 ] || fail "SIGTERM without checkpoint: exit $status"
grep -qF "kerf-dem: interrupted before its first checkpoint (none in $work/n; --checkpoint-every N writes them)" \
  "$work/nerr" || fail "no 'before its first checkpoint' line: $(cat "$work/nerr")"

# Resume: the original run's provenance, the resume appended, and a log that counts from the checkpoint.
"$bin" resume "$work/k" --threads 1 --log-every 1 >"$work/log" 2>"$work/err" || fail "resume: $(cat "$work/err")"
python3 - "$work/k/summary.json" "$scene" "$work/k" "${small[@]}" <<'PY' || fail "resumed provenance (above)"
import json, sys
summary, scene, out, sets = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[5::2]  # the values of --set
p = json.load(open(summary))["provenance"]
h = 14695981039346656037  # FNV-1a 64 of the scene file, as the original run hashed it
for byte in open(scene, "rb").read():
    h = ((h ^ byte) * 1099511628211) % 2**64
assert p["scene"] == scene, p["scene"]
assert p["scene_fnv1a64"] == "%016x" % h, (p["scene_fnv1a64"], "%016x" % h)
assert p["overrides"] == sets, p["overrides"]
assert p["command_line"].split()[1:3] == ["run", scene] and "--checkpoint-every 25" in p["command_line"], p["command_line"]
assert p["scene_as_run"]["cut"]["length_mm"] == 0.3
[r] = p["resumes"]
assert r["command_line"].split()[1:] == ["resume", out, "--threads", "1", "--log-every", "1"], r["command_line"]
assert r["from_sample"] > 0 and r["from_sample"] % 25 == 0, r["from_sample"]
assert r["date"] >= p["date"] and r["date"].endswith("Z"), (r["date"], p["date"])
PY
num='[-+0-9.e]+'
from_step=$(grep -oE "^cut: resumed at step [0-9]+" "$work/log" | awk '{print $5}')
[ -n "$from_step" ] && [ "$from_step" -gt 0 ] || fail "no 'cut: resumed at step N' line: $(head -3 "$work/log")"
last_step=$(grep -E "^cut: step" "$work/log" | tail -1 | awk '{print $3}')
done_line=$(grep -E "^cut: done: " "$work/log")
echo "$done_line" | grep -qE "^cut: done: $((last_step - from_step)) steps since the resume at step $from_step of [0-9]+ particles in $num s, $num particle-steps/s$" ||
  fail "the done line does not count the steps since the resume ($from_step to $last_step): $done_line"
# The first line's rate is of the steps since the resume: had it counted the steps before the resume too, it would
# be about (its step) / (its step - the resume's step) times the average, which the check asks to be large (a
# timing check on a loaded machine needs the margin: the first interval's speed may differ from the average's).
python3 - "$work/log" "$from_step" <<'PY' || fail "a rate counts the steps before the resume (above)"
import re, sys
log = open(sys.argv[1]).read()
resumed_at = int(sys.argv[2])
average = float(re.search(r"^cut: done: .* ([-+0-9.e]+) particle-steps/s$", log, re.M).group(1))
first = re.search(r"^cut: step ([0-9]+) .* \| ([-+0-9.e]+) particle-steps/s \|", log, re.M)
assert first, "no step line"
step, rate = int(first.group(1)), float(first.group(2))
factor = step / (step - resumed_at)  # what counting from step 0 would multiply the rate by
assert factor >= 20, f"the first line comes too late to tell: step {step}, resumed at {resumed_at}"
assert rate < average * factor / 4, (rate, average, factor)
PY
echo "dem_resume_cli: ok"
