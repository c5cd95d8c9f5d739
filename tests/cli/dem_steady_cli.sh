#!/usr/bin/env bash
# A DEM cut's means say whether they are steady (issue 40 item 3): a cut shorter than the entry
# (cut.length_mm=0.1 on the small workpiece) is `results.steady: false` with the reason in summary.json, the
# final line says NOT STEADY with the travel averaged over, and the summary's range is the one of forces.csv;
# replicates carry it per replicate and in their results.
# Usage: dem_steady_cli.sh <dir of built programs> <source dir>
source "$(dirname "$0")/lib/dem_common.sh" "$@"

scene="$src/data/scenes/dem_cut.json"
small=(--set specimen.width_mm=0.4 --set specimen.height_mm=0.25 --set specimen.growth_steps=2000
       --set specimen.relax_steps=500 --set cut.depth_of_cut_mm=0.05 --set output.frame_every_samples=0
       --set cut.speed_m_per_s=2)
"$bin" run "$scene" "${small[@]}" --set cut.length_mm=0.1 --threads 1 --out "$work/short" >"$work/log" 2>"$work/err" ||
  fail "short cut: $(cat "$work/err")"
[ -s "$work/short/forces.png" ] || fail "no forces.png"
python3 - "$work/short/summary.json" "$work/short/forces.csv" "$work/log" <<'PY' || fail "short cut's verdict (above)"
import csv, json, sys
r = json.load(open(sys.argv[1]))["results"]
travel = [float(row["tool_travel_mm"]) for row in csv.DictReader(open(sys.argv[2]))]
assert r["steady"] is False, r["steady"]
assert "the cut travels" in r["not_steady_reason"] and "within the entry" in r["not_steady_reason"], r["not_steady_reason"]
# The range averaged over: from entry_fraction x length to the last sample of forces.csv.
assert abs(r["steady_from_travel_mm"] - 0.25 * 0.1) < 1e-12, r["steady_from_travel_mm"]
assert abs(r["steady_to_travel_mm"] - travel[-1]) < 1e-9, (r["steady_to_travel_mm"], travel[-1])
last = [line for line in open(sys.argv[3]) if line.startswith("cut: cutting force")][-1]
want = "means over {:.4g}-{:.4g} mm of travel (NOT STEADY: {})".format(
    r["steady_from_travel_mm"], r["steady_to_travel_mm"], r["not_steady_reason"])
assert want in last, (want, last)
PY

# Replicates: each row carries its verdict, the results say whether all are steady and which is not.
"$bin" run "$scene" "${small[@]}" --set cut.length_mm=0.03 --replicates 2 --threads 1 --out "$work/r" >"$work/log" \
  2>"$work/err" || fail "replicates: $(cat "$work/err")"
python3 - "$work/r/summary.json" "$work/log" <<'PY' || fail "replicates' verdict (above)"
import json, sys
s = json.load(open(sys.argv[1]))
assert [row["steady"] for row in s["replicates"]] == [False, False], s["replicates"]
assert s["results"]["steady"] is False
assert s["results"]["not_steady_reason"].startswith("replicate 1: the cut travels "), s["results"]
assert "NOT STEADY: replicate 1:" in open(sys.argv[2]).read()
PY
echo "dem_steady_cli: ok"
