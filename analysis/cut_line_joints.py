#!/usr/bin/env python3
"""Is the glass above the edge's path still joined to the glass below when the edge arrives? From a cut's VTK frames
(issue 54 item 3; docs/notes/2026-12-07-edge-zone-steady-stage-1.md, "What a next design has to tell apart").

    PYTHONPATH=build/python python3 analysis/cut_line_joints.py LABEL=DIR [LABEL=DIR ...] [--reach-um R]
        [--csv RUNS.csv]

Each DIR is a cut's output folder written with output.frame_every_samples > 0 (a study's item folders among them);
runs that share a LABEL are packings of one condition. In every frame of the steady travel two criteria, each within
R um of the tool's tip (its lowest point; default 26, the edge zone's reach at radii 10-13 um) and ahead of it:

- *straddles*: a disk tied to the workpiece straddles the cut line (|y - y_cut| < r), its near side ahead of the tip
  and its centre within R + r of it: the edge zone's criterion for intact glass today (dem/procedures/edge_zone.cpp);
- *joined*: an intact joint crosses the cut line (its two disks' centres on either side of it), its lower disk tied,
  its midpoint ahead of the tip and within R + the larger radius of it: glass above the edge's path still joined to
  glass below, which the edge has to cut.

Printed per run, and per label the mean over its runs with its 95 % interval (Student t; kerf.stats): the share of
the steady frames that meet each criterion. --csv writes one row per run.
"""
import argparse
import csv
import pathlib
import sys

import numpy as np

from kerf.frames import steady_frames, tied, tool_tip
from kerf.result_keys import CutResults as R
from kerf.stats import mean_of

DEFAULT_REACH_UM = 26.0


def criteria(frame, y_cut_mm, reach_mm):
    """(straddles, joined) for one frame: see the module's docstring."""
    particles = frame["particles"]
    p, r = particles["position_mm"][:, :2], particles["radius_mm"]
    joints = particles["lines"][particles["intact_elements"] > 0]
    anchored = tied(len(p), joints[:, 0], joints[:, 1], particles["held"] > 0)
    tip = tool_tip(frame)
    # The tool moves towards -x: ahead of the tip is x below it.
    near = np.hypot(p[:, 0] - tip[0], p[:, 1] - tip[1]) < reach_mm + r
    straddles = bool(np.any(anchored & (np.abs(p[:, 1] - y_cut_mm) < r) & (p[:, 0] - r < tip[0]) & near))
    if len(joints) == 0:
        return straddles, False
    i, j = joints[:, 0], joints[:, 1]
    above_i = p[i, 1] > y_cut_mm
    crosses = above_i != (p[j, 1] > y_cut_mm)
    lower = np.where(above_i, j, i)
    mid = 0.5 * (p[i] + p[j])
    within = np.hypot(mid[:, 0] - tip[0], mid[:, 1] - tip[1]) < reach_mm + np.maximum(r[i], r[j])
    joined = bool(np.any(crosses & anchored[lower] & (mid[:, 0] < tip[0]) & within))
    return straddles, joined


def shares(folder, reach_um):
    """(frames, share straddling, share joined) over the run's steady frames."""
    try:
        results, frames = steady_frames(folder)
    except ValueError as e:
        sys.exit(str(e))
    if not frames:
        sys.exit(f"{folder}: no frame in the steady travel")
    met = np.array([criteria(frame, results[R.cut_line_y_mm], 1e-3 * reach_um) for frame in frames])
    return len(met), float(met[:, 0].mean()), float(met[:, 1].mean())


def interval(e):
    return f"{e.value:.3f} [{e.low:.3f}, {e.high:.3f}]" if e.resolved() else f"{e.value:.3f} (n = {e.n})"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("runs", nargs="+", help="LABEL=DIR")
    ap.add_argument("--reach-um", type=float, default=DEFAULT_REACH_UM, help="the zone's reach from the tip (um)")
    ap.add_argument("--csv", help="one row per run")
    a = ap.parse_args(argv)
    if not a.reach_um > 0:
        ap.error(f"--reach-um = {a.reach_um}: expected a reach > 0 um")
    rows = []
    for run in a.runs:
        label, _, folder = run.partition("=")
        frames, straddles, joined = shares(pathlib.Path(folder), a.reach_um)
        rows.append({"label": label, "run": folder, "frames": frames, "straddles_share": straddles,
                     "joined_share": joined})
        print(f"{label} {folder}: {frames} steady frames; a tied disk straddles the cut line {straddles:.3f}, "
              f"joints cross it {joined:.3f}")
    for label in dict.fromkeys(r["label"] for r in rows):
        mine = [r for r in rows if r["label"] == label]
        print(f"{label}: {len(mine)} runs; straddles {interval(mean_of([r['straddles_share'] for r in mine]))}, "
              f"joined {interval(mean_of([r['joined_share'] for r in mine]))}")
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0]), lineterminator="\n")
            w.writeheader()
            w.writerows(rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
