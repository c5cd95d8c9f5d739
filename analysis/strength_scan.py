#!/usr/bin/env python3
"""A scan of one model strength over steady-cut records (issue 41 item 4): force levels and groove effect against it.

    python3 analysis/strength_scan.py --off OFF.csv --point 85=A.csv --point 330=B.csv ... [--label KEY]
                                   [--domain default] [--depth 0.1] [--csv OUT.csv] [--figure OUT.png]

Each --point is a value of the scanned key (in MPa) and the `kerf-dem study` record of the cuts made at it; --off is
the record of the same cuts without the law (the key at 0), drawn right of the largest value. Per point and surface
(regular, rectangular): the main and thrust force per mm of width over the packings with their 95 % intervals (Student
t), the groove effect (rectangular / regular main and thrust, Fieller's interval as in
validation/soda_lime_cutting_steady/trends.py), the subsurface cracks and the deepest one; the experiments' levels and
groove effect (Yang et al. 2018, Table 6, per mm of width) beside them.
"""
import argparse
import csv
import math
import pathlib

from kerf.records import per_width, read_experiments, read_record, reference
from kerf.result_keys import CutResults as R
from kerf.stats import mean_of, ratio

EXPERIMENTS = pathlib.Path(__file__).resolve().parents[1] / "data/experiments/soda_lime_orthogonal_cutting.csv"

SURFACES = ("regular", "rectangular")
FIELDS = ["strength_MPa", "quantity", "surface", "n", "value", "ci95_low", "ci95_high"]


def point_rows(strength, cuts, domain, depth):
    """The rows of one point of the scan (strength None: the law off)."""
    rows = []
    means = {}
    for surface in SURFACES:
        runs = list(cuts.get((domain, surface, round(depth, 6)), {}).values())
        for quantity, values in (("main_force_N_per_mm", [per_width(r, "cutting") for r in runs]),
                                 (R.thrust_force_N_per_mm, [per_width(r, "thrust") for r in runs]),
                                 ("cracks_subsurface", [r.get(R.cracks_subsurface_steady, math.nan) for r in runs]),
                                 ("deepest_subsurface_crack_um",
                                  [r.get(R.subsurface_damage_depth_steady_um, math.nan) for r in runs])):
            e = mean_of(values)
            means[(quantity, surface)] = e
            rows.append([strength, quantity, surface, e.n, e.value, e.low, e.high])
    for force in ("main", "thrust"):
        e = ratio(means[(f"{force}_force_N_per_mm", "rectangular")], means[(f"{force}_force_N_per_mm", "regular")])
        rows.append([strength, f"groove_effect_{force}", "rectangular/regular",
                     min(means[(f"{force}_force_N_per_mm", s)].n for s in SURFACES), e.value, e.low, e.high])
    return rows


def experiments(depth):
    """The experiments' per-width means {(quantity, surface): value} at this depth (the rectangular surface is their
    grooved one) and their groove effect."""
    table = read_experiments(EXPERIMENTS)
    out = {}
    for force in ("main", "thrust"):
        for surface in SURFACES:
            e = reference(table, "experiment", surface, round(depth, 6), force)
            out[(f"{force}_force_N_per_mm", surface)] = e.value if e else math.nan
        out[(f"groove_effect_{force}", "rectangular/regular")] = (
            out[(f"{force}_force_N_per_mm", "rectangular")] / out[(f"{force}_force_N_per_mm", "regular")])
    return out


def fmt(v):
    return f"{v:.4g}" if math.isfinite(v) else "-"


def table(rows, exp):
    lines = [f"{'strength':>9s}  {'quantity':28s} {'surface':20s} {'n':>2s}  value [95 % interval]   experiments"]
    for s, q, surface, n, v, lo, hi in rows:
        e = exp.get((q, surface), math.nan)
        lines.append(f"{'off' if s is None else fmt(s):>9s}  {q:28s} {surface:20s} {n:2d}  {fmt(v)} [{fmt(lo)}, "
                     f"{fmt(hi)}]   {fmt(e)}")
    return "\n".join(lines)


def write_csv(rows, path):
    tmp = path.with_name(path.name + ".tmp")
    with open(tmp, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(FIELDS)
        for s, *rest in rows:
            w.writerow(["off" if s is None else s, *rest])
    tmp.replace(path)


def plot(rows, exp, label, where, path):
    """Three panels against the strength (log axis, the law off at the right): force levels and groove effect (log
    axes), subsurface cracks."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    strengths = sorted({s for s, *_ in rows if s is not None})
    off_x = strengths[-1] * 3 if strengths else 1.0
    x_of = (lambda s: off_x if s is None else s)
    fig, axes = plt.subplots(1, 3, figsize=(14, 5.6))
    panels = (
        (axes[0], [("main_force_N_per_mm", "regular", "regular main", "tab:blue", "o"),
                   ("main_force_N_per_mm", "rectangular", "rectangular main", "tab:orange", "s"),
                   (R.thrust_force_N_per_mm, "regular", "regular thrust", "tab:blue", "^"),
                   (R.thrust_force_N_per_mm, "rectangular", "rectangular thrust", "tab:orange", "v")],
         "force per mm of width (N/mm)", True),
        (axes[1], [("groove_effect_main", "rectangular/regular", "main", "tab:green", "o"),
                   ("groove_effect_thrust", "rectangular/regular", "thrust", "tab:purple", "^")],
         "groove effect (rectangular / regular)", True),
        (axes[2], [("cracks_subsurface", "regular", "regular", "tab:blue", "o"),
                   ("cracks_subsurface", "rectangular", "rectangular", "tab:orange", "s")],
         "subsurface cracks in the steady cut", False),
    )
    for ax, series, ylabel, log_y in panels:
        for i, (q, surface, name, colour, marker) in enumerate(series):
            pts = [(x_of(s), v, lo, hi) for s, qq, ss, _, v, lo, hi in rows if qq == q and ss == surface]
            pts = [p for p in pts if math.isfinite(p[1])]
            if not pts:
                continue
            shift = 1 + 0.04 * (i - (len(series) - 1) / 2)  # side by side on the log axis
            for part, (fmt_, face) in (([p for p in pts if p[0] != off_x], (marker + "-", colour)),
                                        ([p for p in pts if p[0] == off_x], (marker, "white"))):
                if not part:  # the law on: joined; the law off: apart, open markers
                    continue
                lower = [p[1] - p[2] if math.isfinite(p[2]) else 0 for p in part]
                upper = [p[3] - p[1] if math.isfinite(p[3]) else 0 for p in part]
                ax.errorbar([p[0] * shift for p in part], [p[1] for p in part], yerr=[lower, upper], fmt=fmt_,
                            color=colour, mfc=face, capsize=3, label=f"kerf {name}" if face != "white" else None)
            e = exp.get((q, surface), math.nan)
            if math.isfinite(e):
                ax.axhline(e, color=colour, ls=":" if marker in "os" else "-.", lw=1.2, label=f"experiments {name}")
        ax.set_xscale("log")
        if log_y:
            ax.set_yscale("log")
        ticks = strengths + [off_x]
        ax.set_xticks(ticks)
        ax.set_xticklabels([f"{s:g}" for s in strengths] + ["off"])
        ax.xaxis.set_minor_locator(matplotlib.ticker.NullLocator())
        ax.set_xlabel(label)
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=2, frameon=False)
    axes[1].set_ylim(0.1, 4)  # a ratio's unbounded or near-zero interval end leaves the axis
    axes[2].set_ylim(bottom=0)
    fig.suptitle(f"Steady cut, {where}; bars: 95 % intervals over packings (a bar at the axis' edge goes on beyond "
                 "it); open markers: the law off; lines without markers: Yang et al. 2018's experiments", fontsize=9)
    fig.tight_layout()
    tmp = path.with_name(path.stem + ".tmp" + path.suffix)
    fig.savefig(tmp, dpi=130)
    tmp.replace(path)


def parse_point(text):
    value, _, record = text.partition("=")
    try:
        strength = float(value)
    except ValueError:
        strength = math.nan
    if not record or not math.isfinite(strength) or strength <= 0:
        raise argparse.ArgumentTypeError(f"--point: '{text}' is not VALUE=RECORD with a positive value")
    return strength, pathlib.Path(record)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--off", type=pathlib.Path, required=True, help="record of the cuts without the law")
    ap.add_argument("--point", type=parse_point, action="append", required=True, help="VALUE=RECORD")
    ap.add_argument("--label", default="active_window.tied_grain_strength_MPa")
    ap.add_argument("--domain", default="default")
    ap.add_argument("--depth", default=0.1, type=float)
    ap.add_argument("--csv", type=pathlib.Path)
    ap.add_argument("--figure", type=pathlib.Path)
    args = ap.parse_args(argv)
    rows = []
    try:
        for strength, record in sorted(args.point):
            rows += point_rows(strength, read_record(record), args.domain, args.depth)
        rows += point_rows(None, read_record(args.off), args.domain, args.depth)
    except ValueError as e:
        ap.error(str(e))
    exp = experiments(args.depth)
    print(table(rows, exp))
    if args.csv:
        write_csv(rows, args.csv)
    if args.figure:
        plot(rows, exp, args.label, f"{args.domain} window, {args.depth:g} mm", args.figure)


if __name__ == "__main__":
    main()
