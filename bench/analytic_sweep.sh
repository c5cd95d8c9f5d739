#!/usr/bin/env bash
# The 100,000-point sweep written to CSV (docs/performance.md), two builds alternating round by round: the whole
# CLI (parse, predict, format, atomic write). CSV on stdout (one row per run), then the medians and their ratio
# on stderr; both builds must write the same CSV (checked: exit 1 otherwise).
#
#   bash bench/analytic_sweep.sh OLD_KERF_FORCES NEW_KERF_FORCES [ROUNDS] [THREADS] > sweep_bench.csv
set -euo pipefail
old="$1" new="$2" rounds="${3:-5}" threads="${4:-2}"
scene="$(cd "$(dirname "$0")/.." && pwd)/data/scenes/psic_orthogonal.json"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
echo "round,build,threads,wall_s,user_s,system_s"
for round in $(seq "$rounds"); do
  for build in old new; do
    bin=$old; [ "$build" = new ] && bin=$new
    /usr/bin/time -f "%e %U %S" -o "$work/time" "$bin" sweep "$scene" \
      --vary cut.uncut_chip_thickness_um=0.001:10:1000:log --vary tool.edge_radius_um=0:1:100 \
      --csv "$work/$build.csv" --threads "$threads" 2>/dev/null
    read -r wall user sys <"$work/time"
    echo "$round,$build,$threads,$wall,$user,$sys"
  done
  cmp -s "$work/old.csv" "$work/new.csv" || { echo "analytic_sweep: the two builds wrote different CSV" >&2; exit 1; }
done | tee "$work/runs.csv"
python3 - "$work/runs.csv" <<'PY' >&2
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1]), fieldnames=["round", "build", "threads", "wall_s", "user_s", "system_s"]))
rows = [r for r in rows if r["round"] != "round"]
med = {b: {k: statistics.median(float(r[k]) for r in rows if r["build"] == b) for k in ("wall_s", "user_s")}
       for b in ("old", "new")}
for b in ("old", "new"):
    print(f"{b}: median wall {med[b]['wall_s']:.2f} s, user {med[b]['user_s']:.2f} s")
print(f"ratio old/new: wall {med['old']['wall_s'] / med['new']['wall_s']:.2f}, "
      f"user {med['old']['user_s'] / med['new']['user_s']:.2f}")
PY
