#!/usr/bin/env python3
"""Where the steady cuts of the Yang et al. 2018 study leave their cracks (issue 41 item 4): maps from the cuts'
own cracks.csv.

Reads the output folders of `kerf-dem study data/studies/seed000_steady.json` and, optionally, of
`data/studies/seed000_groove_damage.json` (their items/condition_C_seed_S/ folders: summary.json and cracks.csv;
the record files do not hold the cracks). Two figures:

- crack_map_pitch.png: the cracks above the cut line (place `chip`) by position within the groove pitch and depth
  below the surface, per packing: where the ridges between grooves break.
- crack_depth.png: the subsurface cracks under the steady part of each cut per mm of cut and um of depth below
  the cut line, averaged over packings, and the cumulative count from below.
Only the steady part is counted (summary.json's steady_machined_from_x_mm .. steady_machined_to_x_mm). Groove
centres lie at the workpiece's right end - pitch/2 - k pitch (dem/procedures/cut_geometry.cpp, groove_centres); the
right end is taken as specimen.width_mm.

    python3 analysis/seed000_crack_maps.py --study /work/runs/seed000 --damage /work/runs/groove_damage --out DIR
"""
import argparse
import csv
import json
import pathlib

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from kerf.records import cutting_force  # noqa: E402
from kerf.result_keys import ActiveWindowResults as W
from kerf.result_keys import CracksColumns as C
from kerf.result_keys import CutResults as R

# The steady study's conditions at 0.1 mm in the default window and the groove-damage study's layers (their
# condition numbers in data/studies/seed000_steady.json and seed000_groove_damage.json).
STEADY = {"regular": 1, "rectangular, pristine": 2, "trapezoidal, pristine": 3}
DAMAGE = {"rectangular, 25 um layer broken": 1, "rectangular, 25 um layer half broken": 2,
          "rectangular, 50 um layer broken": 3}


def items(root, condition):
    """The finished items of one condition, by seed."""
    found = sorted(pathlib.Path(root, "items").glob(f"condition_{condition}_seed_*"),
                   key=lambda p: int(p.name.rsplit("_", 1)[1]))
    return [p for p in found if (p / "summary.json").exists() and (p / "cracks.csv").exists()]


def steady_cracks(item, place):
    """(x_mm, y_mm) of the cracks of one place within the steady part, and the summary."""
    summary = json.loads((item / "summary.json").read_text())
    r = summary["results"]
    x0, x1 = r[R.steady_machined_from_x_mm], r[R.steady_machined_to_x_mm]
    xy = [(float(row[C.x_mm]), float(row[C.y_mm])) for row in csv.DictReader((item / "cracks.csv").open())
          if row[C.place] == place and x0 <= float(row[C.x_mm]) <= x1]
    return np.array(xy).reshape(-1, 2), summary


def pitch_map(study, out):
    columns = len(STEADY)
    fig, axes = plt.subplots(2, columns, figsize=(4.4 * columns, 7), sharey=True, squeeze=False)
    for col, (label, condition) in enumerate(STEADY.items()):
        for row, item in enumerate(items(study, condition)[:2]):  # the first two packings
            ax = axes[row, col]
            xy, summary = steady_cracks(item, "chip")
            grooves = summary["cut"].get("grooves", {})
            pitch_um = 1000 * grooves.get("pitch_mm", 0.2)
            right_mm = summary["specimen"]["width_mm"]
            phase_um = np.mod((right_mm - xy[:, 0]) * 1000, pitch_um)
            depth_um = (summary["results"][R.surface_y_mm] - xy[:, 1]) * 1000
            cut_um = 1000 * summary["cut"]["cut"]["depth_of_cut_mm"]
            ax.hist2d(phase_um, depth_um, bins=[40, 30], range=[[0, pitch_um], [-20, cut_um + 30]], cmap="magma_r")
            if grooves.get("shape", "none") != "none":
                half = 500 * grooves["width_mm"]
                for edge in (pitch_um / 2 - half, pitch_um / 2 + half):
                    ax.axvline(edge, color="c", lw=0.8)
            ax.axhline(cut_um, color="c", lw=0.8, ls="--")
            ax.set_title(f"{label}, seed {item.name.rsplit('_', 1)[1]}: {len(xy)} cracks", fontsize=9)
            ax.set_xlabel("position within the pitch (um; groove at the cyan lines)", fontsize=8)
    for ax in axes[:, 0]:
        ax.set_ylabel("depth below the surface (um; cut line dashed)", fontsize=8)
    axes[0, 0].invert_yaxis()
    fig.suptitle("Cracks above the cut line (place 'chip') in the steady part, 0.1 mm, default window", fontsize=10)
    fig.tight_layout()
    fig.savefig(out / "crack_map_pitch.png", dpi=90)
    plt.close(fig)


def depth_profile(study, damage, out):
    groups = [(label, items(study, c)) for label, c in STEADY.items()]
    if damage:
        groups += [(label, items(damage, c)) for label, c in DAMAGE.items()]
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.6))
    lines = []
    floor_um = None
    for (label, found), style in zip(groups, ["-", "-", "--", ":", "-", "-."]):
        if not found:
            continue
        hists, forces = [], []
        for item in found:
            xy, summary = steady_cracks(item, "subsurface")
            r = summary["results"]
            floor_um = summary["active_window"][W.damage_depth_limit_um]
            edges = np.arange(0.0, floor_um + 20.0, 10.0)
            depth_um = (r[R.cut_line_y_mm] - xy[:, 1]) * 1000
            h, _ = np.histogram(depth_um, bins=edges)
            hists.append(h / (r[R.steady_machined_to_x_mm] - r[R.steady_machined_from_x_mm]) / 10.0)
            forces.append(cutting_force(r) / summary["results"][R.width_mm])
        mean = np.mean(hists, axis=0)
        centres = 0.5 * (edges[1:] + edges[:-1])
        left.plot(centres, mean, style, label=f"{label}: {len(found)} packings, main {np.mean(forces):.2f} N/mm")
        right.plot(centres, np.cumsum(mean[::-1])[::-1] * 10, style)
        lines.append((label, len(found), mean.sum() * 10, mean[centres > 100].sum() * 10,
                      mean[centres > 200].sum() * 10, np.mean(forces)))
    for ax in (left, right):
        ax.set_xlabel("depth below the cut line (um)")
        if floor_um:
            ax.axvline(floor_um, color="grey", lw=0.6)
    left.set_ylabel("subsurface cracks per mm of cut per um of depth")
    right.set_ylabel("subsurface cracks per mm of cut deeper than this")
    right.set_yscale("log")
    left.set_title("Subsurface cracks under the steady cut, 0.1 mm, default window\n(grey: the window's floor)",
                   fontsize=10)
    right.set_title("Cumulative from below", fontsize=10)
    left.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out / "crack_depth.png", dpi=90)
    plt.close(fig)
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--study", required=True, help="output folder of the seed000_steady study")
    parser.add_argument("--damage", help="output folder of the seed000_groove_damage study")
    parser.add_argument("--out", required=True, help="folder for the figures")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    pitch_map(args.study, out)
    print("| cuts | packings | subsurface cracks per mm of cut | deeper than 100 um below the cut line "
          "| deeper than 200 um | main force (N/mm) |\n|---|---|---|---|---|---|")
    for label, n, total, below100, below200, force in depth_profile(args.study, args.damage, out):
        print(f"| {label} | {n} | {total:.0f} | {below100:.0f} | {below200:.0f} | {force:.3f} |")


if __name__ == "__main__":
    main()
