#!/usr/bin/env bash
# A cut's forces under kerf-forces' names and per mm of width at any thickness (issue 55 item 5), and its
# forces.csv as the cut goes (item 6): the same tiny cut at specimen.thickness_mm 1 and 2 gives totals that double
# and per-mm values that agree (summary.json, its travel windows and forces.csv), main_force_N (deprecated) equal
# to cutting_force_N; a running cut's forces.csv, read again and again while it runs, holds whole rows only, each
# read the start of the finished file, which is what the finished run writes at once (cut_forces_csv); a killed
# run's file holds whole rows.
# Usage: dem_cut_width_running.sh <dir of built programs> <source dir>
source "$(dirname "$0")/lib/dem_common.sh" "$@"

scene="$src/data/scenes/dem_cut.json"
small=(--set specimen.width_mm=0.4 --set specimen.height_mm=0.25 --set specimen.growth_steps=2000
       --set specimen.relax_steps=500 --set cut.depth_of_cut_mm=0.05 --set cut.length_mm=0.04
       --set output.frame_every_samples=0 --set cut.speed_m_per_s=2 --set cut.entry_fraction=0.25)
for t in 1 2; do
  "$bin" run "$scene" "${small[@]}" --set specimen.thickness_mm=$t --threads 1 --out "$work/t$t" >/dev/null \
    2>"$work/err" || fail "cut at thickness $t mm: $(cat "$work/err")"
done
python3 - "$work/t1" "$work/t2" <<'PY' || fail "per mm of width at thickness 1 and 2 mm (above)"
import csv, json, math, sys
one, two = (json.load(open(f"{d}/summary.json"))["results"] for d in sys.argv[1:3])
assert (one["width_mm"], two["width_mm"]) == (1, 2), (one["width_mm"], two["width_mm"])
close = lambda a, b: math.isclose(a, b, rel_tol=1e-9, abs_tol=1e-12)
for r in (one, two):
    assert r["main_force_N"] == r["cutting_force_N"] and r["main_force_std_N"] == r["cutting_force_std_N"], r
for force in ("cutting_force", "thrust_force"):
    assert abs(one[force + "_N"]) > 1e-6, (force, one[force + "_N"])
    assert close(two[force + "_N"], 2 * one[force + "_N"]), (force, one[force + "_N"], two[force + "_N"])
    assert close(two[force + "_N_per_mm"], one[force + "_N_per_mm"]), (force, one, two)
    assert close(one[force + "_N_per_mm"], one[force + "_N"]), force
    for w1, w2 in zip(one["travel_windows"], two["travel_windows"]):
        assert close(w2[force + "_N"], 2 * w1[force + "_N"]) and close(w2[force + "_N_per_mm"], w1[force + "_N_per_mm"])
rows = [list(csv.DictReader(open(f"{d}/forces.csv"))) for d in sys.argv[1:3]]
assert len(rows[0]) == len(rows[1]) > 5
for a, b in zip(*rows):
    for force in ("cutting_force", "thrust_force"):
        assert close(float(b[force + "_N"]), 2 * float(a[force + "_N"])), (a, b)
        assert close(float(b[force + "_N_per_mm"]), float(a[force + "_N_per_mm"])), (a, b)
        assert close(float(b[force + "_N_per_mm"]), float(b[force + "_N"]) / 2), b
    assert a["main_force_N"] == a["cutting_force_N"] and b["main_force_N"] == b["cutting_force_N"]
print("thickness 1 and 2 mm: totals double, per mm of width agree")
PY

# A longer cut, read while it runs: whole rows only, each read the start of the finished file.
long=("${small[@]}" --set cut.length_mm=0.2)
"$bin" run "$scene" "${long[@]}" --threads 1 --out "$work/run" >/dev/null 2>"$work/err" &
pid=$!
reads=0
while kill -0 $pid 2>/dev/null; do
  if [ -e "$work/run/forces.csv" ] && [ ! -e "$work/run/summary.json" ]; then
    cp "$work/run/forces.csv" "$work/snap_$reads.csv" && reads=$((reads + 1))
  fi
  sleep 0.05
done
wait $pid || fail "the long cut: $(cat "$work/err")"
[ $reads -ge 3 ] || fail "only $reads reads of the running forces.csv"
python3 - "$work/run/forces.csv" "$work"/snap_*.csv <<'PY' || fail "a running forces.csv (above)"
import sys
final = open(sys.argv[1], "rb").read()
header = final.split(b"\n", 1)[0]
grew = set()
for path in sys.argv[2:]:
    part = open(path, "rb").read()
    assert final.startswith(part), f"{path}: not the start of the finished file"
    assert part == b"" or part.endswith(b"\n"), f"{path}: a partial row at the end: {part[-80:]!r}"
    lines = part.split(b"\n")[:-1]
    assert not lines or lines[0] == header, path
    assert all(line.count(b",") == header.count(b",") for line in lines), path
    grew.add(len(lines))
assert len(grew) >= 2, f"the running file did not grow between reads: {sorted(grew)}"
print(f"{len(sys.argv) - 2} reads of the running forces.csv, {len(grew)} sizes: whole rows, the finished file's start")
PY

# Killed after a checkpoint: its forces.csv holds whole rows (at least the checkpoint's), no summary.json.
"$bin" run "$scene" "${long[@]}" --threads 1 --checkpoint-every 20 --out "$work/k" >/dev/null 2>&1 &
kill_after_checkpoint $! "$work/k"
[ ! -e "$work/k/summary.json" ] || fail "the killed cut had finished"
python3 - "$work/k/forces.csv" "$work/run/forces.csv" <<'PY' || fail "a killed cut's forces.csv (above)"
import sys
part, final = (open(p, "rb").read() for p in sys.argv[1:3])
assert part.endswith(b"\n") and final.startswith(part), "partial rows or rows the finished cut does not have"
assert part.count(b"\n") >= 1 + 20, part.count(b"\n")  # the header and the checkpoint's samples at least
PY
"$bin" resume "$work/k" --threads 1 >/dev/null 2>"$work/err" || fail "resume: $(cat "$work/err")"
cmp -s "$work/k/forces.csv" "$work/run/forces.csv" || fail "the resumed cut's forces.csv differs from the uninterrupted one"
echo "dem cut width and running forces: ok"
