#!/usr/bin/env python3
"""Steady cuts compared packing by packing, in one figure: for each comparison OTHER - BASE, the main (and thrust)
force difference of every packing both sets have (small points) and their mean with its Student-t 95 % interval
from the paired spread (bar), in N and as a share of the base's mean. Prints the table and draws the figure.

    python3 analysis/plot_paired_differences.py OUT.png "LABEL=BASE_SET,OTHER_SET" [...]

A SET is a study directory or a record file (analysis/compare_steady_cuts.py), with :C and @A-B as there. A comparison
with a force recorded for two packings shows their differences and mean without an interval (with one degree of
freedom it is twelve standard errors wide); for fewer it is left out of that force's panel, and a force no
comparison has for two packings gets no panel.
Needs matplotlib (/usr/bin/python3 on Debian).
"""
import math
import statistics
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from kerf.records import read_set  # noqa: E402
from kerf.stats import t95  # noqa: E402


def paired(base, other, force):
    """Per-packing differences OTHER - BASE of a force, the base's mean over those packings, the seeds."""
    key = f"{force}_force_N"
    pairs = sorted(p for p in set(base) & set(other) if math.isfinite(base[p][key]) and math.isfinite(other[p][key]))
    return [other[p][key] - base[p][key] for p in pairs], [base[p][key] for p in pairs], [p[1] for p in pairs]


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    comparisons = []
    for arg in sys.argv[2:]:
        label, sets = arg.split("=", 1)
        base_spec, other_spec = sets.split(",", 1)
        comparisons.append((label, read_set(base_spec), read_set(other_spec)))
    forces = [f for f in ("main", "thrust") if any(len(paired(b, o, f)[0]) >= 2 for _, b, o in comparisons)]
    if not forces:
        sys.exit("no comparison has a force recorded for two packings")
    fig, axes = plt.subplots(len(forces), 1, figsize=(max(6.0, 1.5 * len(comparisons)), 3.4 * len(forces) + 0.6),
                             squeeze=False, sharex=True)
    for ax, force in zip(axes[:, 0], forces):
        for k, (label, base, other) in enumerate(comparisons):
            diffs, bases, seeds = paired(base, other, force)
            label = label.replace("\n", " ")
            if len(diffs) < 2:
                print(f"{force}, {label}: {len(diffs)} packing(s) recorded, left out")
                continue
            n, mean, base_mean = len(diffs), statistics.mean(diffs), statistics.mean(bases)
            half = t95(n - 1) * statistics.stdev(diffs) / math.sqrt(n) if n >= 3 else math.nan
            interval = (f" [{mean - half:+.3f}, {mean + half:+.3f}]", f" [{100 * (mean - half) / base_mean:+.0f} %, "
                        f"{100 * (mean + half) / base_mean:+.0f} %]") if n >= 3 else ("", "")
            print(f"{force}, {label}: seeds {seeds}, differences {', '.join(f'{d:+.3f}' for d in diffs)} N; mean "
                  f"{mean:+.3f} N{interval[0]}, {100 * mean / base_mean:+.0f} %{interval[1]} of {base_mean:.3f} N")
            ax.plot([k + 0.12] * n, diffs, "o", ms=3, color="0.5", zorder=2)
            ax.errorbar([k], [mean], yerr=[half] if n >= 3 else None, fmt="s" if n >= 3 else "D", color=f"C{k}",
                        mfc=f"C{k}" if n >= 3 else "none", capsize=4, zorder=3)
            top = max(diffs + [mean + half if n >= 3 else mean])
            ax.annotate(f"{100 * mean / base_mean:+.0f} %, {n} packings" + ("" if n >= 3 else "\n(no interval)"),
                        (k, top), textcoords="offset points", xytext=(0, 6), ha="center", va="bottom", fontsize=7,
                        color=f"C{k}")
        ax.margins(y=0.18)
        ax.axhline(0, color="k", lw=0.8)
        ax.set_xticks(range(len(comparisons)))
        ax.set_xticklabels([c[0] for c in comparisons], fontsize=7)
        ax.set_xlim(-0.6, len(comparisons) - 0.4)
        ax.set_ylabel(f"{force} force difference\n(N per mm of width)")
        ax.grid(True, axis="y", alpha=0.3)
    fig.suptitle("packing by packing (grey points): mean (square) and Student-t 95 % interval; open diamond: two "
                 "packings, mean only", fontsize=9)
    fig.tight_layout()
    fig.savefig(sys.argv[1], dpi=130)


if __name__ == "__main__":
    main()
