#!/usr/bin/env python3
"""How far ahead of the tool's tip the intact glass at the cut line is, from a cut's VTK frames (issue 54 item 4).

    PYTHONPATH=build/python python3 analysis/edge_gap_frames.py LABEL=DIR [LABEL=DIR ...] [--out FIGURE.png]

Each DIR is a cut's output folder written with output.frame_every_samples > 0. In every frame of the steady travel
(the run's entry fraction on), the gap is the distance along x from the tool's tip (its lowest point) to the nearest
disk ahead of it that straddles the cut line (|y - y_cut| < r) and is tied to the workpiece (a path of joints with a
bonded element to a held disk), measured to the disk's near side (negative: the disk reaches past the tip). Printed
per run: the frames, the gap's quartiles, and the share of frames in which the tied glass is within 0 (the tip is at
it), 5 um and 26 um (the edge zone's default reach at radii 10-13 um) of the tip. The figure: the gap's cumulative
distribution per run.
"""
import argparse
import pathlib
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from kerf.frames import steady_frames, tied, tool_tip  # noqa: E402
from kerf.result_keys import CutResults as R  # noqa: E402

REACHES_UM = (0.0, 5.0, 26.0)


def gap_um(frame, y_cut_mm):
    """The frame's gap (um) from the tip to the nearest tied disk ahead straddling the cut line; inf if none."""
    particles = frame["particles"]
    p, r = particles["position_mm"][:, :2], particles["radius_mm"]
    joints = particles["lines"][particles["intact_elements"] > 0]
    anchored = tied(len(p), joints[:, 0], joints[:, 1], particles["held"] > 0)
    tip = tool_tip(frame)
    # The tool moves towards -x: ahead of the tip is x below it.
    at_line = anchored & (np.abs(p[:, 1] - y_cut_mm) < r) & (p[:, 0] < tip[0])
    if not at_line.any():
        return np.inf
    return 1e3 * float(np.min(tip[0] - (p[at_line, 0] + r[at_line])))


def gaps(folder):
    """The gaps (um) of the run's frames in its steady travel."""
    try:
        results, frames = steady_frames(folder)
    except ValueError as e:
        sys.exit(str(e))
    return np.array([gap_um(frame, results[R.cut_line_y_mm]) for frame in frames])


def describe(label, g):
    finite = g[np.isfinite(g)]
    q = np.percentile(finite, [25, 50, 75]) if len(finite) else [np.nan] * 3
    shares = ", ".join(f"within {reach:g} um {np.mean(g <= reach):.1%}" for reach in REACHES_UM)
    return (f"{label}: {len(g)} frames, gap quartiles {q[0]:.1f} / {q[1]:.1f} / {q[2]:.1f} um"
            f" (none ahead in {np.mean(~np.isfinite(g)):.0%}); {shares}")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("runs", nargs="+", help="LABEL=DIR")
    ap.add_argument("--out", help="the figure (PNG)")
    a = ap.parse_args(argv)
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for run in a.runs:
        label, _, folder = run.partition("=")
        g = gaps(pathlib.Path(folder))
        print(describe(label, g))
        x = np.sort(np.clip(g[np.isfinite(g)], -10, None))
        ax.step(x, np.arange(1, len(x) + 1) / len(g), where="post", label=label)
    if a.out:
        for reach, name, height in zip(REACHES_UM[1:], ("5 um", "26 um: the zone's reach"), (0.97, 0.90)):
            ax.axvline(reach, color="0.6", lw=0.6, ls="--")
            ax.text(reach + 3, height, name, fontsize=7, color="0.4", va="top")
        ax.set_xlim(-10, None)
        ax.set_xlabel("gap from the tool's tip to the tied glass at the cut line (um; below -10 drawn at -10)",
                      fontsize=9)
        ax.set_ylabel("share of the steady frames (cumulative)", fontsize=9)
        ax.set_ylim(0, 1)
        ax.legend(fontsize=8, loc="lower right")
        ax.set_title("how far ahead of the edge the intact glass begins", fontsize=10)
        fig.tight_layout()
        fig.savefig(a.out, dpi=120)
    return 0


if __name__ == "__main__":
    sys.exit(main())
