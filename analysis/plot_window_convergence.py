#!/usr/bin/env python3
"""The steady cut's mean forces against the window's size: for each series (windows of one workpiece), the mean
main and thrust forces over the packings every set of the series has, with the cuts' own errors
(sqrt(sum sem^2) / n), against the mean number of disks integrated (log scale); a cut without a window (every
disk active) is drawn as a horizontal line with its error band. Prints the table and draws the figure.

    python3 analysis/plot_window_convergence.py OUT.png "LABEL=SET;SET;..." [...]

A SET is a study directory or a record file (analysis/compare_steady_cuts.py), with :C and @A-B as there.

Needs numpy and matplotlib (/usr/bin/python3 on Debian).
"""
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import ScalarFormatter  # noqa: E402

from kerf.records import read_set  # noqa: E402
from kerf.stats import known_mean, own_error  # noqa: E402


def series_points(specs):
    sets = [read_set(spec) for spec in specs]
    common = sorted(set.intersection(*(set(s) for s in sets)))
    if not common:
        sys.exit(f"no packing in every set of {specs}")
    points = []
    for spec, study in zip(specs, sets):
        window = study[common[0]]["window"]
        point = {"spec": spec, "n": len(common), "windowed": window != "none",
                 "window": window if window != "none" else "no window",
                 "disks": known_mean(study[p]["disks"] for p in common)}
        for force in ("main", "thrust"):
            point[force] = known_mean(study[p][f"{force}_force_N"] for p in common)
            point[force + "_se"] = own_error(study, common, force)
        points.append(point)
    return points


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
    fewest_disks, most_disks = float("inf"), 0.0
    for k, arg in enumerate(sys.argv[2:]):
        label, specs = arg.split("=", 1)
        points = series_points(specs.split(";"))
        colour = f"C{k}"
        print(f"{label}:")
        for p in points:
            print(f"  {p['spec']} ({p['window']}): {p['n']} packings, {p['disks']:.0f} disks, main {p['main']:.3f} +- {p['main_se']:.3f} N, "
                  f"thrust {p['thrust']:.3f} +- {p['thrust_se']:.3f} N")
        windows = [p for p in points if p["windowed"]]
        fewest_disks = min([fewest_disks] + [p["disks"] for p in windows])
        most_disks = max([most_disks] + [p["disks"] for p in windows])
        for ax, force in zip(axes, ("main", "thrust")):
            errors = [p[force + "_se"] for p in windows]
            ax.errorbar([p["disks"] for p in windows], [p[force] for p in windows],
                        yerr=errors if all(map(math.isfinite, errors)) else None, fmt="o-", color=colour, capsize=3,
                        label=f"{label} ({points[0]['n']} packings)")
            for p in windows:
                ax.annotate(p["window"], (p["disks"], p[force]), textcoords="offset points", xytext=(5, 5 - 14 * (k % 2)),
                            fontsize=7, color=colour)
            for p in points:
                if p["windowed"]:
                    continue
                ax.axhline(p[force], color=colour, ls="--", lw=1)
                ax.axhspan(p[force] - p[force + "_se"], p[force] + p[force + "_se"], color=colour, alpha=0.15)
                ax.plot([], [], color=colour, ls="--", label=f"{label}: every disk active ({p['disks']:.0f} disks)")
    for ax, force in zip(axes, ("main", "thrust")):
        ax.set_xscale("log")
        if most_disks > 0:
            # From the power of ten below the smallest window (a labelled tick left of it) to room for the
            # largest window's label.
            ax.set_xlim(10 ** math.floor(math.log10(fewest_disks)), 1.6 * most_disks)
        ax.xaxis.set_major_formatter(ScalarFormatter())  # plain disk counts, not powers of ten
        ax.xaxis.set_minor_formatter(ScalarFormatter())
        ax.set_xlabel("disks integrated (mean over the cut)")
        ax.set_ylabel(f"steady {force} force (N per mm of width)")
        ax.set_ylim(bottom=0)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=7, loc="lower left")
    fig.suptitle("windows as depths of cut ahead, behind, below, above the edge", fontsize=9)
    fig.tight_layout()
    fig.savefig(sys.argv[1], dpi=130)


if __name__ == "__main__":
    main()
