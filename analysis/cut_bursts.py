#!/usr/bin/env python3
"""How intermittent a steady cut's force is, from its own forces.csv (issue 41 item 4): how much of the tool's work a
few jams do.

    python3 analysis/cut_bursts.py DIR [DIR ...] [--csv OUT.csv] [--to-travel-mm X] [--figure OUT.png]

Each DIR is a cut's output folder (summary.json, forces.csv) or a study's (DIR/items/*/). Per cut, over the steady
part (the travel the summary's means cover), the travel is cut into bins of a tenth of the depth of cut and the tool's
work in each (main force x travel, summed over the bin's samples) is found. Reported:

* work_share_top_1pc: the share of the steady work done in the 1 % of the bins that hold the most (1 % if the force
  were steady; about half in kerf's undamped cuts, docs/notes/2026-11-29-jams.md);
* travel_share_half_work: the smallest share of the travel (in bins) that holds half the work (0.5 if steady);
* peak_main_force_N: the largest sample of the main force (per the cut's width, as the forces).

Per condition (analysis/cut_energy.py's: glass, window, surface, depth) each with its 95 % interval over packings.
"""
import argparse
import csv
import json
import sys

import numpy as np

from kerf.records import condition_of, cutting_force, folders
from kerf.result_keys import CutResults as R
from kerf.stats import mean_of

MEASURES = ("work_share_top_1pc", "travel_share_half_work", "peak_main_force_N", R.main_force_N)


def work_bins(travel_mm, main_force_n, bin_mm):
    """The tool's work per bin of travel [N mm per mm of width], over whole bins from the first sample (the samples
    are equally spaced in travel: a bin is a whole number of them)."""
    step = float(np.median(np.diff(travel_mm)))
    per_bin = max(1, round(bin_mm / step))
    whole = travel_mm.size // per_bin * per_bin
    return (main_force_n[:whole] * step).reshape(-1, per_bin).sum(axis=1)


def concentration(work):
    """(share of the work in the top 1 % of bins, smallest share of bins holding half the work)."""
    ranked = np.sort(work)[::-1]
    total = ranked.sum()
    if total <= 0:
        return float("nan"), float("nan")
    top = max(1, len(ranked) // 100)
    half = int(np.searchsorted(np.cumsum(ranked) / total, 0.5)) + 1
    return float(ranked[:top].sum() / total), half / len(ranked)


def steady_part(folder, to_travel_mm=None):
    """A cut's summary and its (travel [mm], main force [N per mm of width]) samples over the steady part, or over the
    steady part up to `to_travel_mm` of travel (to compare cuts of different lengths over the same travel)."""
    summary = json.loads((folder / "summary.json").read_text())
    results = summary["results"]
    forces = np.loadtxt(folder / "forces.csv", delimiter=",", skiprows=1, ndmin=2)
    end_mm = results[R.steady_to_travel_mm]
    if to_travel_mm is not None:
        end_mm = min(end_mm, to_travel_mm)
    steady = (forces[:, 0] >= results[R.steady_from_travel_mm]) & (forces[:, 0] <= end_mm)
    return summary, forces[steady, 0], forces[steady, 2]


def cut_bursts(folder, to_travel_mm=None):
    """One cut: its condition, seed and measures over the steady part, or over its part up to `to_travel_mm` of travel
    (the main force is then the mean of the samples there)."""
    summary, travel, main = steady_part(folder, to_travel_mm)
    bin_mm = 0.1 * summary["cut"]["cut"]["depth_of_cut_mm"]
    top, half = concentration(work_bins(travel, main, bin_mm))
    seed = summary.get("study_item", {}).get("scene", {}).get("specimen", {}).get("seed", summary["specimen"]["seed"])
    mean = cutting_force(summary["results"]) if to_travel_mm is None else float(main.mean())
    measures = {"work_share_top_1pc": top, "travel_share_half_work": half,
                "peak_main_force_N": float(main.max()), R.main_force_N: mean}
    return condition_of(summary), seed, measures


def cumulative_work(folder, to_travel_mm=None):
    """The tool's work from the start of the steady part [mJ per mm of width] against the travel from there [mm]."""
    _, travel, main = steady_part(folder, to_travel_mm)
    step = float(np.median(np.diff(travel)))
    return travel - travel[0], np.cumsum(main) * step


def figure(folders_and_cuts, path, to_travel_mm=None):
    """One panel per surface and depth; each cut's cumulative work, coloured by its glass and window (the legend names
    each once): a steady force is a straight line, a jam a step."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    panels = sorted({(key[2], key[3]) for _, (key, _, _) in folders_and_cuts}, key=lambda p: (p[0] != "regular", p))
    kinds = sorted({(key[0], key[1]) for _, (key, _, _) in folders_and_cuts})
    # The legend below the panels, one line per kind (its names are long): room for it in the figure's height.
    legend_in = 0.18 * len(kinds) + 0.2
    fig, axes = plt.subplots(1, len(panels), figsize=(5.5 * len(panels), 4.2 + legend_in), squeeze=False, sharey=True)
    handles = {}
    for ax, (surface, depth) in zip(axes[0], panels):
        for folder, (key, _, _) in folders_and_cuts:
            if (key[2], key[3]) != (surface, depth):
                continue
            kind = kinds.index((key[0], key[1]))
            travel, work = cumulative_work(folder, to_travel_mm)
            (line,) = ax.plot(travel, work, color=f"C{kind}", lw=1)
            handles.setdefault(kind, line)
        ax.set_title(f"{surface}, depth of cut {depth:g} mm")
        ax.set_xlabel("tool travel over the steady part (mm)")
        ax.grid(alpha=0.3)
    axes[0][0].set_ylabel("tool's work (mJ per mm of width)")
    fig.legend([handles[k] for k in sorted(handles)], [f"{kinds[k][0]}, {kinds[k][1]}" for k in sorted(handles)],
               fontsize=8, loc="lower center", frameon=False)
    fig.tight_layout(rect=(0, legend_in / (4.2 + legend_in), 1, 1))
    fig.savefig(path, dpi=130)


def table(cuts):
    """Per condition: {measure: Estimate over packings}."""
    by = {}
    for key, _, m in cuts:
        by.setdefault(key, []).append(m)
    return {k: {name: mean_of([m[name] for m in rows]) for name in MEASURES} for k, rows in sorted(by.items())}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dirs", nargs="+")
    ap.add_argument("--csv", help="also write one row per cut here")
    ap.add_argument("--figure", help="a PNG of each cut's cumulative work against its travel")
    ap.add_argument("--to-travel-mm", type=float, help="only the steady part up to this travel (cuts of other lengths)")
    a = ap.parse_args(argv)
    found = list(folders(a.dirs, needs="forces.csv"))
    cuts = [cut_bursts(f, a.to_travel_mm) for f in found]
    if a.figure:
        figure(list(zip(found, cuts)), a.figure, a.to_travel_mm)
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["glass", "window", "surface", "depth_of_cut_mm", "seed", *MEASURES])
            for key, seed, m in cuts:
                w.writerow([*key, seed, *(m[name] for name in MEASURES)])
    print("steady part, bins of 0.1 depth of cut: mean over packings [95 % interval]")
    for key, row in table(cuts).items():
        def fmt(e):
            return f"{e.value:.3g}" + (f" [{e.low:.3g}, {e.high:.3g}]" if e.resolved() else "")
        print(f"  {' '.join(map(str, key))}: n {row[R.main_force_N].n}, " +
              ", ".join(f"{name} {fmt(e)}" for name, e in row.items()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
