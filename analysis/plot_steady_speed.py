#!/usr/bin/env python3
"""The undamped steady cut against the tool speed, several packings per speed (data/studies/steady_speed_undamped.json):
the main and thrust forces per mm with two error bars (the cuts' own batch-means errors combined, sqrt(sum sem^2) / n,
and the spread between packings, std / sqrt(n)), beside the chip's momentum flux rho v^2 h (the force that only
accelerating the uncut layer to the tool speed would take) added to the slowest speed's mean. Prints Markdown
tables: per speed the means, both errors, how intermittent the cuts are and their cost; the weighted fit
F = F0 + k v with the slope's significance; whether the cuts' own errors agree with the spread between packings
(a chi-square test); how regular the impacts are; and the main force per mm of travel, averaged over all cuts, to
show where the entry transient ends.

    python3 analysis/plot_steady_speed.py OUT.png STUDY_DIR [STUDY_DIR...]

Each STUDY_DIR is a study's output (its items/ directory), e.g. the study above and a `kerf-dem run ... --replicates N`
of the bundled scene on other seeds (its DIR/replicates): the items are pooled by speed.
"""
import json
import math
import pathlib
import sys

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from kerf.records import cutting_force, cutting_force_column, intermittency  # noqa: E402
from kerf.result_keys import CutResults as R
from kerf.result_keys import ForcesCsvColumns as F


def items(study_dir):
    """Every finished item of the study (its directory renamed from .partial-*), read from its own summary.json, so
    the figure can be drawn while the study runs on."""
    rows = []
    for item_dir in sorted((study_dir / "items").glob("condition_*_seed_*")):
        summary = json.loads((item_dir / "summary.json").read_text())
        results = summary["results"]
        r = {"speed": summary["cut"]["cut"]["speed_m_per_s"], "wall": summary["study_item"]["wall_time_s"],
             "density": summary["material"]["density_kg_per_m3"], "depth_m": summary["cut"]["cut"]["depth_of_cut_mm"] * 1e-3,
             "windows": [cutting_force(w) for w in results[R.travel_windows]]}
        r["main"], r["main_sem"] = cutting_force(results), cutting_force(results, "sem_N")
        r["thrust"], r["thrust_sem"] = results[R.thrust_force_N], results[R.thrust_force_sem_N]
        r.update(intermittency(item_dir, results[R.steady_from_travel_mm]))
        r.update(impact_regularity(item_dir, results[R.steady_from_travel_mm]))
        rows.append(r)
    return rows


def impact_regularity(item_dir, steady_from_mm, threshold_n=5.0, merge_mm=0.02):
    """The tool's impacts over the steady part: a main force rising above threshold_n starts one, and starts closer
    than merge_mm to the previous one belong to it. Returns impacts per mm, the coefficient of variation of their
    spacing (1 for impacts at random, a Poisson process) and the Fano factor of their count per mm of travel
    (variance / mean; 1 for Poisson, below 1 for impacts more regular than chance)."""
    forces = np.genfromtxt(item_dir / "forces.csv", delimiter=",", names=True)
    steady = forces[F.tool_travel_mm] >= steady_from_mm
    travel, touching = forces[F.tool_travel_mm][steady], forces[cutting_force_column(forces.dtype.names)][steady] > threshold_n
    starts = travel[1:][touching[1:] & ~touching[:-1]]
    impacts = [starts[0]]
    for x in starts[1:]:
        if x - impacts[-1] > merge_mm:
            impacts.append(x)
    spacing = np.diff(impacts)
    counts, _ = np.histogram(impacts, bins=np.arange(travel[0], travel[-1], 1.0))
    return {"impacts_per_mm": len(impacts) / (travel[-1] - travel[0]), "spacing_cv": spacing.std() / spacing.mean(),
            "fano": counts.var() / counts.mean()}


def chi_square_lower_tail(x, dof):
    """P(chi^2_dof <= x): the regularized lower incomplete gamma P(dof / 2, x / 2), by its series."""
    a, z = dof / 2, x / 2
    term = total = 1 / a
    for k in range(1, 1000):
        term *= z / (a + k)
        total += term
        if term < 1e-15 * total:
            break
    return math.exp(a * math.log(z) - z - math.lgamma(a)) * total


def condition(rows, key):
    means = np.array([r[key] for r in rows])
    n = len(means)
    within = math.sqrt(sum(r[key + "_sem"] ** 2 for r in rows)) / n
    between = means.std(ddof=1) / math.sqrt(n) if n > 1 else float("nan")
    return means.mean(), within, between


def weighted_line(speeds, means, sems):
    """Weighted least squares F = F0 + k v; returns F0, k and their standard errors."""
    w = 1 / np.asarray(sems) ** 2
    a = np.vstack([np.ones_like(speeds), speeds]).T
    cov = np.linalg.inv(a.T @ (a * w[:, None]))
    f0, k = cov @ (a.T @ (w * np.asarray(means)))
    return f0, k, math.sqrt(cov[0, 0]), math.sqrt(cov[1, 1])


def main():
    out = sys.argv[1]
    rows = [r for study_dir in sys.argv[2:] for r in items(pathlib.Path(study_dir))]
    speeds = sorted({r["speed"] for r in rows})
    by_speed = {v: [r for r in rows if r["speed"] == v] for v in speeds}
    stats = {(v, key): condition(by_speed[v], key) for v in speeds for key in ("main", "thrust")}
    fits = {}
    for key in ("main", "thrust"):
        m = [stats[(v, key)] for v in speeds]
        sems = [max(s[1], s[2]) if not math.isnan(s[2]) else s[1] for s in m]
        fits[key] = weighted_line(np.array(speeds, float), [s[0] for s in m], sems)
    counts = sorted({len(by_speed[v]) for v in speeds})
    packings = f"{counts[0]}" if len(counts) == 1 else f"{counts[0]}-{counts[-1]}"
    fig, axes = plt.subplots(1, 2, figsize=(10.5, 4.4), sharex=True)
    for ax, key, title in ((axes[0], "main", "main force"), (axes[1], "thrust", "thrust force")):
        m = [stats[(v, key)] for v in speeds]
        grid = np.geomspace(speeds[0], speeds[-1], 50)
        f0, k, f0_sem, k_sem = fits[key]
        ax.plot(grid, f0 + k * grid, ls=":", color="C1",
                label=f"fit F0 + k v: F0 {f0:.3f} +- {f0_sem:.3f} N, k {1e3 * k:.0f} +- {1e3 * k_sem:.0f} mN s/m")
        ax.errorbar([v * 0.97 for v in speeds], [s[0] for s in m], [s[1] for s in m], marker="o", capsize=3,
                    label="error: the cuts' own (batch means)")
        ax.errorbar([v * 1.03 for v in speeds], [s[0] for s in m], [s[2] for s in m], marker="none", ls="none",
                    capsize=3, color="grey", label="error: spread between packings")
        if key == "main":
            r0 = by_speed[speeds[0]][0]
            flux = r0["density"] * grid**2 * r0["depth_m"] * 1e-3  # N per mm of width
            ax.plot(grid, m[0][0] + flux - flux[0], ls="--", color="k", lw=1,
                    label=f"{speeds[0]:g} m/s mean + rho v^2 h (chip momentum)")
        ax.set_xscale("log")
        ax.set_xticks(speeds)
        ax.set_xticklabels([f"{s:g}" for s in speeds])
        ax.minorticks_off()
        ax.set_xlabel("tool speed (m/s)")
        ax.set_ylabel(f"steady {title} per 1 mm width (N)")
        ax.set_title(f"{title}: mean of {packings} packings +- standard error", fontsize=10)
        ax.set_ylim(bottom=0)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc="lower right")
    fig.suptitle("Undamped regular 0.1 mm steady cut (12 mm workpiece, 11 mm travel per packing) against the tool speed")
    fig.tight_layout()
    fig.savefig(out, dpi=120)

    print("| speed (m/s) | packings | main force (N) | thrust force (N) | tool in contact | largest 5 % carry | wall s per cut |")
    print("|---:|---:|---|---|---:|---:|---:|")
    for v in speeds:
        rs = by_speed[v]
        cells = []
        for key in ("main", "thrust"):
            mean, within, between = stats[(v, key)]
            cells.append(f"{mean:.3f} +- {within:.3f} ({100 * within / mean:.1f} %; packings +- {between:.3f})")
        print(f"| {v:g} | {len(rs)} | {cells[0]} | {cells[1]} | {100 * np.mean([r['contact'] for r in rs]):.1f} % "
              f"| {100 * np.mean([r['top5'] for r in rs]):.0f} % | {np.mean([r['wall'] for r in rs]):.0f} |")
    for key in ("main", "thrust"):
        f0, k, f0_sem, k_sem = fits[key]
        print(f"\n{key}: weighted fit F = F0 + k v (errors: the larger of the two per speed): F0 {f0:.3f} +- {f0_sem:.3f} N, "
              f"k {1e3 * k:.1f} +- {1e3 * k_sem:.1f} mN per m/s ({k / k_sem:+.1f} standard errors)")
    print("\nThe cuts' own errors against the spread between packings: r = (std / sqrt(n)) / (sqrt(sum sem^2) / n) per speed; "
          "if the cuts' own were right, sum (n - 1) r^2 follows chi-square on sum (n - 1) degrees of freedom:")
    for key in ("main", "thrust"):
        ratios = [(len(by_speed[v]) - 1, stats[(v, key)][2] / stats[(v, key)][1]) for v in speeds if len(by_speed[v]) > 1]
        x, dof = sum(d * r * r for d, r in ratios), sum(d for d, _ in ratios)
        print(f"{key}: r {', '.join(f'{r:.2f}' for _, r in ratios)}; chi-square {x:.1f} on {dof}: "
              f"P(lower) {chi_square_lower_tail(x, dof):.1e}, P(upper) {1 - chi_square_lower_tail(x, dof):.2f}")
    print("\nImpacts (main force above 5 N; starts within 20 um merged), mean over the packings:")
    for v in speeds:
        rs = by_speed[v]
        print(f"{v:g} m/s: {np.mean([r['impacts_per_mm'] for r in rs]):.1f} per mm, spacing CV "
              f"{np.mean([r['spacing_cv'] for r in rs]):.2f}, Fano factor per mm {np.mean([r['fano'] for r in rs]):.2f}")
    print("\nMain force per mm of travel, mean over every cut of every speed (N):")
    windows = np.array([r["windows"] for r in rows])
    spread = windows.std(axis=0, ddof=1) / math.sqrt(len(rows))
    print(" | ".join(f"{k}-{k + 1} mm: {m:.3f} +- {s:.3f}" for k, (m, s) in enumerate(zip(windows.mean(axis=0), spread))))


if __name__ == "__main__":
    main()
