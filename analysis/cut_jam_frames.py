#!/usr/bin/env python3
"""A jam and what follows it, from a cut's VTK frames (issue 41 item 4; docs/notes/2026-11-29-jams.md).

    PYTHONPATH=build/python python3 analysis/cut_jam_frames.py DIR --zoom K1,K2 --wide K3,K4 --out FIGURE.png

DIR is a cut's output folder written with output.frame_every_samples > 0 (frame_K.vtp, walls_K.vtp, forces.csv,
summary.json). The figure: the frames K1, K2 near the tool's tip, the frames K3, K4 over the whole window, and the
main force against travel between K3 and K4. Disks are coloured by whether a path of joints with a bonded element
ties them to a held disk (the workpiece) or not (loose: chips, debris); black lines are those joints; the disks the
tool's faces touch are outlined in green. Frames are read with kerf.dem.read_frames (the kerf module, built in
build/python).
"""
import argparse
import json
import pathlib
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection, PatchCollection  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402

import kerf  # noqa: E402
from kerf.frames import samples_per_frame, tied, tool_tip  # noqa: E402


def segment_distance(p, a, b):
    ab = b - a
    t = np.clip(((p - a) @ ab) / (ab @ ab), 0, 1)
    return np.hypot(*(p - (a + t[:, None] * ab)).T)


def draw_frame(ax, folder, k, half_width_mm, below_mm, above_mm):
    frame = kerf.dem.read_frames(folder, steps=[k])[0]  # frame_K.vtp is time step K
    particles, walls = frame["particles"], frame["walls"]
    p, r = particles["position_mm"][:, :2], particles["radius_mm"]
    n = len(p)
    joints = particles["lines"][particles["intact_elements"] > 0]
    i, j = joints[:, 0], joints[:, 1]
    anchored = tied(n, i, j, particles["held"] > 0)
    w = walls["position_mm"][:, :2]
    faces = [(w[a], w[b]) for a, b in walls["lines"]]
    tip = tool_tip(frame)
    x0, x1 = tip[0] - 2 * half_width_mm, tip[0] + 0.5 * half_width_mm
    y0, y1 = tip[1] - below_mm, tip[1] + above_mm
    show = (p[:, 0] > x0 - 0.05) & (p[:, 0] < x1 + 0.05) & (p[:, 1] > y0 - 0.05) & (p[:, 1] < y1 + 0.05)
    touching = np.zeros(n, bool)
    for a, b in faces:
        touching |= segment_distance(p, a, b) < r
    disks = PatchCollection([Circle(p[u], r[u]) for u in np.flatnonzero(show)], lw=0.2)
    disks.set_facecolor(np.where(anchored[show][:, None], [[0.45, 0.6, 0.9, 1]], [[0.9, 0.45, 0.35, 1]]))
    disks.set_edgecolor(np.where(touching[show][:, None], [[0, 0.6, 0, 1]], [[0.3, 0.3, 0.3, 1]]))
    disks.set_linewidth(np.where(touching[show], 1.5, 0.2))
    ax.add_collection(disks)
    keep = show[i] | show[j]
    ax.add_collection(LineCollection(np.stack([p[i[keep]], p[j[keep]]], axis=1), colors="k", lw=0.4))
    for a, b in faces:
        ax.plot([a[0], b[0]], [a[1], b[1]], color="g", lw=1.5)
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("equal")
    ax.tick_params(labelsize=7)
    return tip


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dir")
    ap.add_argument("--zoom", required=True, help="two frame numbers drawn near the tool's tip")
    ap.add_argument("--wide", required=True, help="two frame numbers drawn over the window; the force between them")
    ap.add_argument("--out", required=True)
    ap.add_argument("--every", type=int, help="samples per frame (default: the run's output.frame_every_samples)")
    a = ap.parse_args(argv)
    folder = pathlib.Path(a.dir)
    summary = json.loads((folder / "summary.json").read_text())
    # Samples per frame: --every, else the run's override of output.frame_every_samples (its provenance).
    every = a.every or samples_per_frame(summary) or ap.error("--every: the samples per frame")
    depth = summary["cut"]["cut"]["depth_of_cut_mm"]
    forces = np.loadtxt(folder / "forces.csv", delimiter=",", skiprows=1)
    zoom, wide = [int(k) for k in a.zoom.split(",")], [int(k) for k in a.wide.split(",")]
    fig = plt.figure(figsize=(13, 8.5))
    grid = fig.add_gridspec(2, 3, height_ratios=[1, 1.1])
    for col, k in enumerate(zoom):
        ax = fig.add_subplot(grid[0, col])
        draw_frame(ax, folder, k, 0.6 * depth, 0.6 * depth, 1.2 * depth)
        ax.set_title(f"near the tip, frame {k}: main force {forces[min(k * every, len(forces) - 1), 2]:.1f} N/mm", fontsize=9)
    ax = fig.add_subplot(grid[0, 2])
    lo, hi = wide[0] * every, min(wide[1] * every, len(forces) - 1)
    ax.plot(forces[lo:hi, 0], forces[lo:hi, 2], lw=0.8)
    for k in zoom:
        ax.axvline(forces[min(k * every, len(forces) - 1), 0], color="g", lw=0.6, ls="--")
    ax.set_xlabel("tool travel (mm)", fontsize=8)
    ax.set_ylabel("main force (N per mm of width)", fontsize=8)
    ax.set_title(f"main force, frames {wide[0]}-{wide[1]} (green: the frames left)", fontsize=9)
    ax.tick_params(labelsize=7)
    for col, k in enumerate(wide):
        ax = fig.add_subplot(grid[1, col])
        draw_frame(ax, folder, k, 4 * depth, 5 * depth, 1.5 * depth)
        ax.set_title(f"the window, frame {k}: travel {forces[min(k * every, len(forces) - 1), 0]:.3f} mm", fontsize=9)
    fig.text(0.70, 0.25, "blue: tied to the workpiece by intact joints\nred: loose (no such path)\n"
             "black: joints with a bonded element\ngreen outline: disks touching the tool\ncoordinates in mm",
             fontsize=9, va="center")
    fig.suptitle(f"{summary['material']['name']}, {summary['cut']['grooves']['shape']} surface, depth of cut {depth} mm",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(a.out, dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main())
