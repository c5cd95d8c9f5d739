#!/usr/bin/env python3
"""The scaling model of `kerf-dem study` over MPI ranks (docs/cluster.md), on paper: an event simulation of
the study's scheduler (dem/study/study_scheduler.cpp, StudyScheduler) with W worker ranks, fed with measured per-item times.

Item times: the 12 cuts of the Yang et al. 2018 study in docs/performance-dem-study.csv (one thread each, measured
2026-11-22), taken in a fixed shuffled cycle. Coordinator: a serial cost per message and a round-trip latency per item,
measured with `bench/study_throughput.json`'s synthetic twin (docs/performance.md, "Studies").

Studies modelled:
  seed000   the validation's 18 cuts (fixed count: 6 conditions x 3 packings)
  adaptive  4 conditions, adaptive replicates that stop at 100 packings each (a mean within 5 % for a 50 %
            scatter: (0.5 / 0.05)^2; max_count 200); packings beyond the decided count that idle workers ran ahead are waste

Usage: python3 bench/study_scaling_model.py [docs/performance-dem-study.csv]
"""
import csv
import heapq
import random
import sys

SERIAL_S = 0.0005     # the coordinator's own work per item (parse, bookkeeping, log line): 0.47 ms measured, 2 workers
MAX_COUNT = 200       # adaptive: replicates.max_count (idle workers run ahead up to it)
ROUND_TRIP_S = 0.003  # a worker's wait for its next item (polling naps): 2.2-3.3 ms measured, 1 worker


def simulate(times, conditions, needed, workers, adaptive):
    """Returns (wall s, useful item-seconds, items run, items wasted)."""
    issued = [0] * conditions
    done = [dict() for _ in range(conditions)]  # replicate -> its time
    decided = [None if adaptive else needed] * conditions
    minimum = 5 if adaptive else needed
    k_time = 0

    def next_item():
        nonlocal k_time
        # replicate-major first: what every condition needs (min_count, or the fixed count)
        best = None
        for c in range(conditions):
            need = decided[c] if decided[c] is not None else minimum
            if issued[c] < need and (best is None or issued[c] < issued[best]):
                best = c
        if best is None and adaptive:
            for c in range(conditions):
                if decided[c] is None and issued[c] < MAX_COUNT and (best is None or issued[c] < issued[best]):
                    best = c
        if best is None:
            return None
        item = (best, issued[best], times[k_time % len(times)])
        issued[best] += 1
        k_time += 1
        return item

    def finished():
        return all(decided[c] is not None and all(k in done[c] for k in range(decided[c])) for c in range(conditions))

    clock, coordinator_free = 0.0, 0.0
    events, idle, run = [], list(range(workers)), 0
    while True:
        while idle:
            item = next_item()
            if item is None:
                break
            w = idle.pop()
            coordinator_free = max(coordinator_free, clock) + SERIAL_S
            heapq.heappush(events, (coordinator_free + ROUND_TRIP_S + item[2], w, item))
            run += 1
        if not events:
            break
        clock, w, (c, k, t) = heapq.heappop(events)
        done[c][k] = t
        if decided[c] is None and all(j in done[c] for j in range(needed)):
            decided[c] = needed
        idle.append(w)
        if finished() and not events:
            break
    used = [t for c in range(conditions) for k, t in done[c].items() if k < needed]
    return clock, sum(used), run, run - len(used)


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "docs/performance-dem-study.csv"
    times = [float(r["cut_wall_time_s"]) for r in csv.DictReader(open(path))]
    random.Random(1).shuffle(times)
    print(f"item times: {len(times)} measured cuts, {min(times):.0f}-{max(times):.0f} s, mean {sum(times) / len(times):.0f} s")
    print("| study | workers | wall | efficiency | items run (wasted) |")
    print("|---|---|---|---|---|")
    for name, conditions, needed, adaptive in (("seed000", 6, 3, False), ("adaptive", 4, 100, True)):
        for workers in (1, 2, 4, 8, 16, 18, 32, 64, 128, 256, 400, 1000):
            wall, useful, run, wasted = simulate(times, conditions, needed, workers, adaptive)
            eff = useful / (workers * wall)
            unit = f"{wall / 3600:.2f} h" if wall >= 3600 else f"{wall / 60:.1f} min"
            print(f"| {name} | {workers} | {unit} | {100 * eff:.1f} % | {run} ({wasted}) |")


if __name__ == "__main__":
    main()
