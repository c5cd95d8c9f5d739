#!/usr/bin/env bash
# Study throughput (issue 21, "Benchmark"): bench/study_throughput.json (12 small cuts) run the four ways a
# study runs on this machine, the ways alternating round by round, each into a fresh directory. CSV on stdout;
# every way must give the same conditions.csv (checked: exit 1 otherwise). Leave the machine otherwise idle.
#
#   bash bench/study_throughput.sh [KERF_DEM] [ROUNDS] > study_throughput.csv
set -euo pipefail
bin="${1:-build/tools/kerf-dem}"
rounds="${2:-2}"
study="$(dirname "$0")/study_throughput.json"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export KERF_DATA_DIR="${KERF_DATA_DIR:-$(cd "$(dirname "$0")/../data" && pwd)}"
mpi=(mpirun --allow-run-as-root --oversubscribe)
ways=("threads_1" "threads_2")
if "$bin" study --help | grep -q "across ranks" && command -v mpirun >/dev/null; then ways+=("mpi_np_2" "mpi_np_3"); fi
echo "round,way,items,study_wall_s,items_per_hour,mean_item_wall_s"
for round in $(seq "$rounds"); do
  for way in "${ways[@]}"; do
    out="$work/$way-$round"
    case "$way" in
      threads_1) "$bin" study "$study" --out "$out" --threads 1 >/dev/null 2>&1 ;;
      threads_2) "$bin" study "$study" --out "$out" --threads 2 >/dev/null 2>&1 ;;
      mpi_np_2) "${mpi[@]}" -np 2 "$bin" study "$study" --out "$out" >/dev/null 2>&1 ;;
      mpi_np_3) "${mpi[@]}" -np 3 "$bin" study "$study" --out "$out" >/dev/null 2>&1 ;;
    esac
    python3 - "$out" "$round" "$way" <<'PY'
import csv, json, statistics, sys
out, round_, way = sys.argv[1:]
s = json.load(open(out + "/summary.json"))
walls = [float(r["wall_time_s"]) for r in csv.DictReader(open(out + "/items.csv"))]
print(f"{round_},{way},{s['items']},{s['wall_time_s']:.3f},{3600 * s['items'] / s['wall_time_s']:.0f},{statistics.mean(walls):.3f}")
PY
    cmp -s "$work/threads_1-1/conditions.csv" "$out/conditions.csv" || { echo "$way round $round: conditions.csv differs" >&2; exit 1; }
  done
done
