#!/usr/bin/env python3
"""The steady cut's subsurface damage against depth: the crack events of each cut's cracks.csv below the cut line,
within the steadily machined stretch (summary.json's steady_machined_from_x_mm .. _to_x_mm), counted in bins of
depth and divided by the stretch's length (cracks per mm of cut per 25 um of depth), averaged over the packings of
each set; the window's floor (active_window.damage_depth_limit_um) marked. Prints the table and draws the figure.

    python3 analysis/plot_crack_depth.py OUT.png LABEL=STUDY_DIR[:C] [LABEL=STUDY_DIR[:C] ...]

STUDY_DIR:C takes only condition C's items. Needs numpy and matplotlib (/usr/bin/python3 on Debian).
"""
import csv
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from kerf.records import item_dirs  # noqa: E402
from kerf.result_keys import ActiveWindowResults as W
from kerf.result_keys import CracksColumns as C
from kerf.result_keys import CutResults as R

BIN_UM = 25.0


def profile(spec):
    counts, floor, n = None, None, 0
    for item in item_dirs(spec):
        s = json.loads((item / "summary.json").read_text())
        r = s["results"]
        y_cut, x_from, x_to = r[R.cut_line_y_mm], r[R.steady_machined_from_x_mm], r[R.steady_machined_to_x_mm]
        lo, hi = min(x_from, x_to), max(x_from, x_to)
        floor = s.get("active_window", {}).get(W.damage_depth_limit_um)
        depths = []
        with open(item / "cracks.csv") as f:
            for row in csv.DictReader(f):
                x, y = float(row[C.x_mm]), float(row[C.y_mm])
                if lo <= x <= hi and y < y_cut:
                    depths.append(1e3 * (y_cut - y))
        edges = np.arange(0, 1000 + BIN_UM, BIN_UM)
        h, _ = np.histogram(depths, bins=edges)
        h = h / (hi - lo)
        counts = h if counts is None else counts + h
        n += 1
    if n == 0:
        sys.exit(f"no items in {spec}")
    return counts / n, floor, n


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out = sys.argv[1]
    fig, ax = plt.subplots(figsize=(7, 4.2))
    table = {}
    for arg in sys.argv[2:]:
        label, spec = arg.split("=", 1)
        c, floor, n = profile(spec)
        centres = np.arange(len(c)) * BIN_UM + BIN_UM / 2
        last = int(np.nonzero(c)[0].max()) + 1 if c.any() else 1
        line, = ax.plot(centres[:last], c[:last], marker="o", ms=3, label=f"{label} ({n} packings)")
        if floor:
            ax.axvline(floor, color=line.get_color(), ls=":", lw=1)
        table[label] = (c, floor, n)
    ax.set_xlabel("depth below the cut line (um); dotted: the window's floor")
    ax.set_ylabel(f"cracks per mm of cut per {BIN_UM:g} um of depth")
    ax.set_yscale("log")
    ax.set_title("subsurface cracks under the steady cut (steadily machined stretch)", fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    labels = list(table)
    print("depth_um," + ",".join(labels))
    rows = max(len(table[l][0]) for l in labels)
    for i in range(rows):
        vals = [table[l][0][i] if i < len(table[l][0]) else 0 for l in labels]
        if not any(vals):
            continue
        print(f"{i * BIN_UM:.0f}-{(i + 1) * BIN_UM:.0f}," + ",".join(f"{v:.1f}" for v in vals))
    for l in labels:
        print(f"{l}: floor {table[l][1]} um, {table[l][2]} packings")


if __name__ == "__main__":
    main()
