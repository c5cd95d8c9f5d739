#!/usr/bin/env python3
"""The Yang et al. 2018 trends from a record of steady cuts (issue 41): does the DEM reproduce what the experiments
show, and is each trend the same in the two domains?

    PYTHONPATH=build/python python3 validation/soda_lime_cutting_steady/trends.py [RECORD.csv ...] [--out DIR]
        [--experiments CSV] [--report]

(the module kerf from the build: its kerf.stats and kerf.records; scripts/validate.sh sets the path.)

RECORD (default data/studies/results/seed000_steady.csv) is the record that `kerf-dem study
data/studies/seed000_steady.json` writes, one row per cut: domain, surface (regular, rectangular, trapezoidal),
depth_of_cut_mm, seed, main_force_N, thrust_force_N, width_mm, ... Everything here comes from the record and the
experiments' table alone, so the numbers outlive the machine that ran the cuts. Several records merge (one model
choice's cuts spread over two studies); a cut in two of them is an error.

Statistics (kerf.stats, python/kerf/stats.py; the record readers kerf.records). A condition's mean is over its packings (the independent samples); its standard error is the
sample standard deviation / sqrt(n), with n - 1 degrees of freedom. A ratio of two conditions' means (depth
effect, groove effect, trapezoid against rectangle) is treated as a ratio of independent means (the cuts of two
conditions share a packing seed, but an intermittent cut decorrelates them; the paired spread is printed beside
it): its 95 % interval is Fieller's (Fieller 1954; exact for normal means, unbounded when the denominator is
not resolved from zero), with Student's t at the Welch-Satterthwaite degrees of freedom of the delta-method
variance. A difference of two estimates (kerf against the experiments, one domain against the
other) uses the delta-method standard errors, sqrt(se1^2 + se2^2), with Welch-Satterthwaite degrees of freedom.
Verdicts come from those intervals only: 'differs' when the 95 % interval of the difference excludes 0; 'agrees'
when it contains 0 and is narrow enough to have seen a difference that matters, every point of it within
AGREEMENT_MARGIN (50 %) of the value compared against (the experiments', or the large domain's): an interval from
-100 % to +900 % holds 0 but could not have told a factor of two; 'not resolved' otherwise, or when an interval
cannot be formed (fewer than two packings, or an unbounded ratio).

Writes DIR/trends.csv (one row per trend and source), DIR/cost.csv (per condition: CPU time per cut, the main
force's spread between packings, the packings and CPU-hours a 10 % and a 5 % standard error take) and
DIR/trends.png (+ .pdf): each trend with both domains,
the experiments and the paper's DEM, with their intervals; DIR/decomposition.png: each surface's force split through
the two depths of cut into an edge part and a chip part (Albrecht's decomposition, F = F0 + k h). With --report also
DIR/report.md, the acceptance of validation/soda_lime_cutting_steady/ (exit 1 while a verdict asked is not resolved;
the thrust's and those the experiments cannot tell are shown, not asked), with the packings and CPU-hours each verdict
not resolved would take at the present spread (packings_factor).
"""
import argparse
import csv
import json
import math
import pathlib
import statistics
import sys

from kerf.records import GROOVED, per_width, read_experiments, read_records, reference
from kerf.result_keys import CutResults as R
from kerf.stats import combination, difference, mean_of, packings_factor, ratio, verdict

ROOT = pathlib.Path(__file__).resolve().parents[2]
RECORD = ROOT / "data/studies/results/seed000_steady.csv"
STUDY = ROOT / "data/studies/seed000_steady.json"
EXPERIMENTS = ROOT / "data/experiments/soda_lime_orthogonal_cutting.csv"
DOMAINS = ("default", "large")


class Sources:
    """Per condition means of kerf (by domain) and of the references (experiment, paper_dem)."""

    def __init__(self, cuts, experiments, planned=None):
        """planned: the (domain, surface, depth_mm) conditions the study runs (None: every domain runs every
        condition); a trend is expected in a domain only where the study runs all its conditions."""
        self.cuts, self.experiments, self.planned = cuts, experiments, planned
        self.needs = {}  # trend name -> the domains expected to give it (filled by trends())
        self.conditions = {}  # trend name -> its [(surface, depth_mm)] (filled by trends())
        self.thrust = set()  # the trends of the thrust force (filled by trends())

    def domains_for(self, conditions):
        if self.planned is None:
            return DOMAINS
        return tuple(d for d in DOMAINS if all((d, s, h) in self.planned for s, h in conditions))

    def kerf(self, domain, surface, depth, quantity):
        rows = self.cuts.get((domain, surface, depth), {}).values()
        if quantity in ("main", "thrust"):
            return mean_of([per_width(r, quantity) for r in rows])
        return mean_of([r.get(quantity, math.nan) for r in rows])

    def reference(self, source, surface, depth, quantity):
        return reference(self.experiments, source, surface, depth, quantity)


def trends(src):
    """Every trend: (name, group, {source: Estimate}), sources 'kerf default', 'kerf large', 'experiment',
    'paper DEM'; ratios of condition means (levels: the means themselves)."""
    out = []

    def add(name, group, conditions, make_kerf, make_ref, quantity=None):
        src.needs[name] = src.domains_for(conditions)
        src.conditions[name] = conditions
        if quantity == "thrust":
            src.thrust.add(name)
        values = {}
        for domain in DOMAINS:
            e = make_kerf(domain)
            if e is not None and math.isfinite(e.value):
                values[f"kerf {domain}"] = e
        for source, label in (("experiment", "experiment"), ("paper_dem", "paper DEM")):
            e = make_ref(source) if make_ref else None
            if e is not None and math.isfinite(e.value):
                values[label] = e
        if values:
            out.append((name, group, values))

    def ref_ratio(source, num, den, q):
        a, b = src.reference(source, *num, q), src.reference(source, *den, q)
        return ratio(a, b) if a and b else None

    for q in ("main", "thrust"):
        for surface in ("regular",) + GROOVED:
            for depth in (0.1, 0.2):
                add(f"{q} force per mm, {surface} {depth} mm (N/mm)", "level", [(surface, depth)],
                    lambda dom, s=surface, d=depth, q=q: src.kerf(dom, s, d, q),
                    lambda source, s=surface, d=depth, q=q: src.reference(source, s, d, q))
    for q in ("main", "thrust"):
        for surface in ("regular",) + GROOVED:
            add(f"depth effect {q}, {surface} (0.2 / 0.1 mm)", "ratio", [(surface, 0.2), (surface, 0.1)],
                lambda dom, s=surface, q=q: ratio(src.kerf(dom, s, 0.2, q), src.kerf(dom, s, 0.1, q)),
                lambda source, s=surface, q=q: ref_ratio(source, (s, 0.2), (s, 0.1), q), q)
    for q in ("main", "thrust"):
        for surface in GROOVED:
            for depth in (0.1, 0.2):
                add(f"groove effect {q}, {surface} / regular at {depth} mm", "ratio",
                    [(surface, depth), ("regular", depth)],
                    lambda dom, s=surface, d=depth, q=q: ratio(src.kerf(dom, s, d, q), src.kerf(dom, "regular", d, q)),
                    lambda source, s=surface, d=depth, q=q: ref_ratio(source, (s, d), ("regular", d), q), q)
    # Albrecht's decomposition through the two depths: F(h) = F0 + k h, the intercept F0 = 2 F(0.1) - F(0.2) (a force
    # that does not grow with the depth of cut: the edge's) and the slope k = (F(0.2) - F(0.1)) / 0.1 mm (the chip's).
    def through_depths(c, at_01, at_02):
        return combination([(c[0], at_01), (c[1], at_02)]) if at_01 and at_02 else None

    for q in ("main", "thrust"):
        for surface in ("regular",) + GROOVED:
            for name, unit, c in (("depth-independent", "N/mm", (2.0, -1.0)),
                                  ("per mm of depth", "N/mm per mm", (-10.0, 10.0))):
                add(f"{q} force {name}, {surface} ({unit})", "decomposition", [(surface, 0.1), (surface, 0.2)],
                    lambda dom, s=surface, q=q, c=c: through_depths(c, src.kerf(dom, s, 0.1, q),
                                                                    src.kerf(dom, s, 0.2, q)),
                    lambda source, s=surface, q=q, c=c: through_depths(c, src.reference(source, s, 0.1, q),
                                                                       src.reference(source, s, 0.2, q)))
    for depth in (0.1, 0.2):
        add(f"trapezoidal / rectangular thrust at {depth} mm", "ratio",
            [("trapezoidal", depth), ("rectangular", depth)],
            lambda dom, d=depth: ratio(src.kerf(dom, "trapezoidal", d, "thrust"),
                                       src.kerf(dom, "rectangular", d, "thrust")), None, "thrust")
        # The damage as the subsurface cracks under the steady cut: their depth is censored in both domains
        # (damage_floors), their number within the domain is not.
        for surface in GROOVED:
            add(f"subsurface cracks under the steady cut, {surface} / regular at {depth} mm", "ratio",
                [(surface, depth), ("regular", depth)],
                lambda dom, s=surface, d=depth: ratio(src.kerf(dom, s, d, R.cracks_subsurface_steady),
                                                     src.kerf(dom, "regular", d, R.cracks_subsurface_steady)),
                None)
    return out


def damage_floors(study_path):
    """{(domain, surface, depth_mm): (floor_um, largest disk diameter_um)} from the study and its scene: how deep
    below the cut line a crack can be seen, the nearer of the window's floor (below_depths depths of cut) and the
    workpiece's bottom (its height less the depth of cut). {} when the study file is absent."""
    study_path = pathlib.Path(study_path)
    if not study_path.is_file():
        return {}
    study = json.loads(study_path.read_text())
    scene = json.loads((study_path.parent / study["scene"]).read_text())
    height_mm, diameter_um = scene["specimen"]["height_mm"], 2 * scene["specimen"]["radius_max_um"]
    floors = {}
    for c in study["conditions"]["list"]:
        tags, depth = c["tags"], c["cut.depth_of_cut_mm"]
        below = c.get("active_window.below_depths", scene.get("active_window", {}).get("below_depths", math.inf))
        floor_mm = min(below * depth, height_mm - depth)
        floors[(tags["domain"], tags["surface"], round(float(tags["depth_of_cut_mm"]), 6))] = (1000 * floor_mm,
                                                                                             diameter_um)
    return floors


def damage_section(cuts, floors):
    """report.md's lines on the damage depth under the steady cut: each condition's deepest crack against the
    depth at which the domain stops seeing cracks; a depth within a disk diameter of it is censored (a lower
    bound), which the crack-count trends above avoid."""
    md = ["## Damage depth under the steady cut (reported)", "",
          "| domain | surface | depth of cut (mm) | packings | deepest crack below the cut line (um) | floor (um) | "
          "censored |", "|---|---|---:|---:|---:|---:|---:|"]
    censored_all = True
    for key in sorted(cuts):
        depths = [r.get(R.subsurface_damage_depth_steady_um, math.nan) for r in cuts[key].values()]
        depths = [d for d in depths if isinstance(d, float) and math.isfinite(d)]
        if not depths or key not in floors:
            continue
        floor, diameter = floors[key]
        censored = sum(d >= floor - diameter for d in depths)
        censored_all = censored_all and censored == len(depths)
        md.append(f"| {key[0]} | {key[1]} | {key[2]:g} | {len(depths)} | {min(depths):.0f}-{max(depths):.0f} | "
                  f"{floor:.0f} | {censored} of {len(depths)} |")
    md += ["", "The floor is the nearer of the window's floor and the workpiece's bottom (the large window reaches "
           "below the 1 mm workpiece). " + ("Every cut's damage reaches it: the depths are lower bounds, and the "
                                           "damage trend is the crack count above." if censored_all else
                                           "A censored depth is a lower bound."), ""]
    return md


COST_TARGETS = (0.10, 0.05)  # the main force's relative standard error over packings a user may ask for


def costs(cuts):
    """What an answer costs, per condition (issue 41 item 5; docs/cluster.md): the recorded cuts, their median CPU
    time, the spread of the main force between packings (coefficient of variation, sample sd / mean) and, for each
    target relative standard error e in COST_TARGETS, the packings it takes, n = ceil((cv / e)^2) (at least 2: a
    spread needs two), and their CPU-hours at the median cut. Rows without two packings have no spread and no n."""
    out = []
    for (domain, surface, depth), by_seed in sorted(cuts.items()):
        rows = list(by_seed.values())
        cpu = [r["cpu_time_s"] for r in rows if isinstance(r.get("cpu_time_s"), float)]
        mains = [per_width(r, "main") for r in rows]
        row = {"domain": domain, "surface": surface, "depth_of_cut_mm": depth, "cuts": len(rows),
               "cpu_s_per_cut": statistics.median(cpu) if cpu else math.nan,
               "main_force_cv": statistics.stdev(mains) / statistics.fmean(mains) if len(mains) >= 2 else math.nan}
        for e in COST_TARGETS:
            cv = row["main_force_cv"]
            n = max(2, math.ceil((cv / e) ** 2 - 1e-9)) if math.isfinite(cv) else None  # 4.000000001 is 4
            row[f"packings_for_{e:.0%}"] = n
            row[f"cpu_h_for_{e:.0%}"] = n * row["cpu_s_per_cut"] / 3600 if n else math.nan
        out.append(row)
    return out


def cost_section(cost_rows):
    """The report's cost table (Markdown lines)."""
    head = "| domain | surface | depth (mm) | cuts | CPU s per cut (median) | main force cv | " + " | ".join(
        f"packings, CPU-h for {e:.0%}" for e in COST_TARGETS) + " |"
    md = ["## What an answer costs", "",
          "CPU seconds are the record's (one thread, on the machine that ran the cut, under whatever load it "
          "had: an upper bound of a quiet core's). The packings a target standard error of the main force needs "
          "are (cv / target)^2 from the spread between the packings so far (itself uncertain with few packings).",
          "", head, "|---|---|---:|---:|---:|---:|" + "---:|" * len(COST_TARGETS)]
    for r in cost_rows:
        cv = f"{r['main_force_cv']:.2f}" if math.isfinite(r["main_force_cv"]) else "—"
        cells = [f"{r[f'packings_for_{e:.0%}']}, {r[f'cpu_h_for_{e:.0%}']:.1f}" if r[f"packings_for_{e:.0%}"]
                 else "—" for e in COST_TARGETS]
        md.append(f"| {r['domain']} | {r['surface']} | {r['depth_of_cut_mm']:g} | {r['cuts']} | "
                  f"{r['cpu_s_per_cut']:.0f} | {cv} | " + " | ".join(cells) + " |")
    return md + [""]


def against_experiments(trend, source):
    """The name of a verdict of `source` ('kerf default', ...) against the experiments (the report's, the acceptance's
    and to_resolve's)."""
    return f"{trend} ({source}) against the experiments"


def between_domains(trend):
    """The name of a trend's domain-robustness verdict."""
    return f"{trend}: default against large domain"


def to_resolve(rows, all_trends, src, cost_rows):
    """Each of kerf's verdicts not resolved in `rows` (rows_of's; the acceptance's: ratios against the experiments,
    and default against large), with what resolving it would take at the present spread (packings_factor):
    [{verdict, packings now (per condition), factor, why, packings per condition, CPU-hours more}]. The CPU-hours are
    each condition's median cut times its added packings; two verdicts sharing a condition share its cuts (not summed
    here)."""
    cpu = {(r["domain"], r["surface"], r["depth_of_cut_mm"]): r["cpu_s_per_cut"] for r in cost_rows}
    values_of = {name: values for name, _, values in all_trends}
    out = []

    def add(label, name, domains, terms, against):
        k, why = packings_factor(terms, against)
        keys = [(dom, s, h) for dom in domains for s, h in src.conditions[name]]
        now = [len(src.cuts.get(key, {})) for key in keys]
        row = {"verdict": label, "now": now, "factor": k, "why": why}
        if math.isfinite(k):
            need = [math.ceil(k * n - 1e-9) for n in now]
            row["need"] = need
            row["cpu_h"] = sum((m - n) * cpu.get(key, math.nan) for m, n, key in zip(need, now, keys)) / 3600
        out.append(row)

    open_rows = [r for r in rows if r["group"] == "ratio" and r["source"].startswith("kerf")]
    for name in dict.fromkeys(r["trend"] for r in open_rows):
        values = values_of[name]
        for r in open_rows:  # against the experiments first, then between the domains
            if r["trend"] == name and r.get("against_experiment") == "not resolved":
                e, exp = values[r["source"]], values["experiment"]
                add(against_experiments(name, r["source"]), name, (r["source"][5:],),
                    [(1.0, e, True), (-1.0, exp, False)], exp)
        for r in open_rows:
            if r["trend"] == name and r.get("domain_robust") == "not resolved":
                default, large = values["kerf default"], values["kerf large"]
                add(between_domains(name), name, DOMAINS, [(1.0, default, True), (-1.0, large, True)], large)
    return out


def resolve_section(pending):
    """The report's lines on what the verdicts not resolved would take."""
    if not pending:
        return []
    md = ["## What the verdicts not resolved would take", "",
          "At the present spread between packings (the delta method's interval narrowing as one over the square "
          "root of the packings, the experiments' not at all), the packings each condition of the trend would need "
          "for the verdict to resolve, either way, and the CPU-hours they add at the median cut. A projection, not "
          "a promise: the spread itself is uncertain with few packings. Verdicts sharing a condition share its cuts.",
          "", "| verdict | packings now | x packings | packings needed | CPU-hours more |", "|---|---:|---:|---:|---:|"]
    for r in pending:
        now = ", ".join(map(str, r["now"]))
        if math.isfinite(r["factor"]):
            md.append(f"| {r['verdict']} | {now} | {r['factor']:.1f} | {', '.join(map(str, r['need']))} | "
                      f"{r['cpu_h']:.1f} |")
        else:
            why = ("never by kerf's packings: the experiments' own interval is wider than the +-50 % an 'agrees' "
                   "asks" if r["why"] == "experiments" else "beyond 100x the packings")
            md.append(f"| {r['verdict']} | {now} | — | {why} | — |")
    return md + [""]


def rows_of(all_trends):
    """trends.csv's rows: each source's estimate, its difference from the experiment (and, for kerf's default
    domain, from the large one) with the verdicts."""
    rows = []
    for name, group, values in all_trends:
        exp = values.get("experiment")
        for source, e in values.items():
            row = {"trend": name, "group": group, "source": source, "n": e.n if group == "level" else "",
                   "value": e.value, "ci95_low": e.low, "ci95_high": e.high}
            if exp is not None and source != "experiment":
                d = difference(e, exp)
                row.update(minus_experiment=d.value, minus_experiment_low=d.low, minus_experiment_high=d.high,
                           against_experiment=verdict(d, exp))
            if source == "kerf default" and "kerf large" in values:
                d = difference(e, values["kerf large"])
                row.update(default_minus_large=d.value, default_minus_large_low=d.low,
                           default_minus_large_high=d.high, domain_robust=verdict(d, values["kerf large"]))
            rows.append(row)
    return rows


FIELDS = ["trend", "group", "source", "n", "value", "ci95_low", "ci95_high", "minus_experiment",
          "minus_experiment_low", "minus_experiment_high", "against_experiment", "default_minus_large",
          "default_minus_large_low", "default_minus_large_high", "domain_robust"]


def write_csv(rows, path):
    tmp = path.with_suffix(".csv.tmp")
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS, lineterminator="\n")
        w.writeheader()
        for r in rows:
            w.writerow({k: f"{v:.4g}" if isinstance(v, float) else v for k, v in r.items()})
    tmp.replace(path)


STYLE = {"kerf default": ("o", "tab:blue"), "kerf large": ("s", "tab:orange"), "experiment": ("D", "black"),
         "paper DEM": ("^", "tab:green")}


def plot(all_trends, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    # Both on log axes (the paper's 2D DEM gives some 20 times the experiments' force per mm); an interval that
    # leaves the axis (unbounded, or below zero) is drawn to its edge.
    groups = [("level", "force per mm of width (N/mm, log scale)", (0.03, 30)),
              ("ratio", "ratio (log scale)", (0.03, 10))]
    heights = [sum(1 for _, g, _ in all_trends if g == group) for group, _, _ in groups]
    fig, axes = plt.subplots(1, 2, figsize=(15, 0.32 * max(heights) + 2.2))
    for ax, (group, xlabel, (x_min, x_max)) in zip(axes, groups):
        items = [(n, v) for n, g, v in all_trends if g == group]
        offsets = {s: (k - 1.5) * 0.18 for k, s in enumerate(STYLE)}
        for y, (name, values) in enumerate(items):
            for source, e in values.items():
                marker, colour = STYLE[source]
                lo = e.low if math.isfinite(e.low) else e.value
                hi = e.high if math.isfinite(e.high) else e.value
                lo, hi = min(max(lo, x_min), e.value), max(min(hi, x_max), e.value)
                ax.errorbar(e.value, y + offsets[source], xerr=[[max(0, e.value - lo)], [max(0, hi - e.value)]],
                            fmt=marker, color=colour, ms=4, capsize=2, lw=1)
        ax.set_yticks(range(len(items)))
        ax.set_yticklabels([n for n, _ in items], fontsize=7)
        ax.invert_yaxis()
        ax.set_xlabel(xlabel)
        ax.set_xscale("log")
        ax.set_xlim(x_min, x_max)
        if group == "ratio":
            ax.axvline(1, color="grey", lw=0.5)
        ax.grid(axis="x", lw=0.3)
    handles = [plt.Line2D([], [], marker=m, color=c, ls="", label=s) for s, (m, c) in STYLE.items()]
    fig.suptitle("Yang et al. 2018 trends: kerf's steady cut in two domains against the experiments and the paper's "
                 "DEM (95 % intervals; a bar at the axis' edge goes on beyond it)", y=0.99, fontsize=10)
    fig.legend(handles=handles, loc="upper center", ncol=4, frameon=False, bbox_to_anchor=(0.5, 0.955))
    fig.tight_layout(rect=(0, 0, 1, 0.91))
    fig.savefig(path)
    fig.savefig(path.with_suffix(".pdf"))


def plot_decomposition(all_trends, path):
    """The main and thrust force's edge part and chip part per surface (linear axes), each source with its interval;
    the paper's DEM, some twenty times the experiments' force per mm, is left out."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    items = [(n, v) for n, g, v in all_trends if g == "decomposition"]
    if not items:
        return
    fig, axes = plt.subplots(1, 2, figsize=(13, 0.3 * len(items) + 2.4))
    sources = [s for s in STYLE if s != "paper DEM"]
    offsets = {s: (k - 1) * 0.22 for k, s in enumerate(sources)}
    for ax, kind, xlabel in ((axes[0], "depth-independent", "edge part F0 = 2 F(0.1) - F(0.2) (N/mm)"),
                             (axes[1], "per mm of depth", "chip part k = (F(0.2) - F(0.1)) / 0.1 mm (N/mm per mm)")):
        mine = [(n.replace(f" {kind}", "").split(" (")[0], v) for n, v in items if kind in n]
        for y, (_, values) in enumerate(mine):
            for source in sources:
                e = values.get(source)
                if e is None:
                    continue
                marker, colour = STYLE[source]
                err = [[e.value - e.low], [e.high - e.value]] if e.resolved() else None
                ax.errorbar(e.value, y + offsets[source], xerr=err, fmt=marker, color=colour, ms=4, capsize=2, lw=1)
        ax.set_yticks(range(len(mine)))
        ax.set_yticklabels([n for n, _ in mine], fontsize=8)
        ax.invert_yaxis()
        ax.axvline(0, color="grey", lw=0.5)
        ax.set_xlabel(xlabel)
        ax.grid(axis="x", lw=0.3)
    handles = [plt.Line2D([], [], marker=STYLE[s][0], color=STYLE[s][1], ls="", label=s) for s in sources]
    fig.suptitle("The force through the two depths of cut, F(h) = F0 + k h: kerf's steady cut against the "
                 "experiments (95 % intervals; the default window spans twice the millimetres at 0.2 mm)", fontsize=10)
    fig.legend(handles=handles, loc="upper center", ncol=3, frameon=False, bbox_to_anchor=(0.5, 0.94))
    fig.tight_layout(rect=(0, 0, 1, 0.88))
    fig.savefig(path)


def fmt_interval(value, low, high):
    """'0.64 [0.52, 0.77]'; '—' for a missing value, an open end for an unbounded interval."""
    if not isinstance(value, float) or not math.isfinite(value):
        return "—"
    if not (isinstance(low, float) and math.isfinite(low) and isinstance(high, float) and math.isfinite(high)):
        return f"{value:.3g} (no interval)"
    return f"{value:.3g} [{low:.3g}, {high:.3g}]"


def acceptance(rows, needs=None, thrust=frozenset(), pending=()):
    """The steady case's acceptance (validation/soda_lime_cutting_steady/README.md): every trend compared with the
    experiments has a resolved verdict in each domain the study runs it in (needs: trend -> domains; default
    both), agrees or differs, and so has its domain robustness. Only kerf's verdicts are asked, and of those not
    the ones no number of kerf's packings can resolve: the paper's DEM's verdicts are shown beside, and so are the
    verdicts the experiments' own interval leaves open (pending, to_resolve's rows: why 'experiments'). The thrust's
    (trend names in `thrust`) are reported with whatever the packings reach (issue 41: the packings stop on the main
    force's standard error), not asked. Returns (resolved, [what is not], [what is shown, not asked, and why])."""
    cannot_tell = {r["verdict"] for r in pending if r["why"] == "experiments"}
    missing, shown = [], []

    def ask(label, trend):
        if label in cannot_tell:
            shown.append(f"{label} (the experiments cannot tell)")
        elif trend in thrust:
            shown.append(f"{label} (thrust)")
        else:
            missing.append(label)

    for r in rows:
        if r["group"] != "ratio" or not r["source"].startswith("kerf"):
            continue
        if "against_experiment" in r and r["against_experiment"] == "not resolved":
            ask(against_experiments(r["trend"], r["source"]), r["trend"])
        if "domain_robust" in r and r["domain_robust"] == "not resolved":
            ask(between_domains(r["trend"]), r["trend"])
    ratios_with_experiment = {r["trend"] for r in rows if r["group"] == "ratio" and r["source"] == "experiment"}
    for trend in sorted(ratios_with_experiment):
        sources = {r["source"] for r in rows if r["trend"] == trend}
        for domain in (needs or {}).get(trend, DOMAINS):
            if f"kerf {domain}" not in sources:
                missing.append(f"{trend} (kerf {domain}): no cuts")
    return not missing, missing, shown


def report(rows, cuts, record_path, floors=None, src=None, pending=None):
    """The steady case's report.md: what is compared and why, the trends with their verdicts, the levels, and
    the acceptance line. Every verdict is the one rows_of drew from the intervals."""
    record = pathlib.Path(record_path).resolve()
    record_path = record.relative_to(ROOT) if record.is_relative_to(ROOT) else record
    n_cuts = sum(len(v) for v in cuts.values())
    cpu_h = sum(r.get("cpu_time_s", 0.0) for v in cuts.values() for r in v.values()
                if isinstance(r.get("cpu_time_s"), float)) / 3600
    dates = [r.get("date") for v in cuts.values() for r in v.values() if isinstance(r.get("date"), str)]
    latest = f", the latest recorded {max(dates)}" if dates else ""
    md = ["# Validation: soda-lime glass, the Yang et al. 2018 trends in the steady cut", "",
          f"From the record `{record_path}` alone ({n_cuts} cuts{latest}, {cpu_h:.1f} CPU-hours; `kerf-dem study "
          "data/studies/seed000_steady.json` adds to it, this report is `python3 validation/soda_lime_cutting_steady/trends.py --report`).",
          "", "## What is compared, and why", "",
          "- **Trends, not levels.** The undamped steady cut's force per mm of width moves with the integrated "
          "domain (docs/dem.md, 'Steady-state cuts'); a ratio between two conditions cut in the same domain may "
          "not. The acceptance is on the ratios the experiments show: the depth effect (0.2 / 0.1 mm) and the groove "
          "effect (grooved / regular), main and thrust; the levels are reported beside.",
          "- **Two domains.** `default`: the scene's window (7, 3, 4, 4 depths of cut); `large`: a window fixed in "
          "millimetres (1.4, 0.7, 1.0, 0.8 mm). A trend the two domains give alike (its difference's interval holds "
          "0, within +-50 % of the large domain's value) does not depend on the window.",
          "- **Against the experiments** (Yang et al. 2018, Table 6, 25.4 mm wide; per mm of width for the levels): "
          "each kerf trend's 95 % interval (Fieller's, packings as the samples) and the experiments' (their three "
          "tests); the verdict is on the difference: *differs* when its 95 % interval excludes 0 (resolved), *agrees* "
          "when it holds 0 and lies within +-50 % of the experiments' value (narrow enough to have seen a difference "
          "that matters), *not resolved* when it is wider, or when no interval can be formed. The paper's DEM is "
          "shown beside.",
          "- **Acceptance.** Every one of kerf's verdicts asked resolved, either way: the case then says what the DEM "
          "reproduces and what it does not. It fails while one is not resolved (more packings: rerun the study). "
          "Shown, not asked: the paper's DEM's verdicts and those the experiments' own interval leaves open (more "
          "packings of kerf's cannot resolve them), and the thrust's (reported with whatever the packings reach: "
          "they stop on the main force's standard error).", ""]
    ratio_rows = [r for r in rows if r["group"] == "ratio"]
    level_rows = [r for r in rows if r["group"] == "level"]

    def table(selected, with_verdicts):
        trends_in_order = list(dict.fromkeys(r["trend"] for r in selected))
        head = "| trend | kerf default | kerf large | experiment | paper's DEM |"
        rule = "|---|---:|---:|---:|---:|"
        if with_verdicts:
            head += " default vs experiment | large vs experiment | default - large |"
            rule += "---|---|---|"
        out = [head, rule]
        for trend in trends_in_order:
            by = {r["source"]: r for r in selected if r["trend"] == trend}
            cell = lambda s: fmt_interval(by[s]["value"], by[s]["ci95_low"], by[s]["ci95_high"]) if s in by else "—"
            line = f"| {trend} | {cell('kerf default')} | {cell('kerf large')} | {cell('experiment')} | " \
                   f"{cell('paper DEM')} |"
            if with_verdicts:
                verdict = lambda s, k: by[s].get(k, "—") if s in by else "—"
                line += f" {verdict('kerf default', 'against_experiment')} | " \
                        f"{verdict('kerf large', 'against_experiment')} | {verdict('kerf default', 'domain_robust')} |"
            out.append(line)
        return out

    md += ["## Trends (95 % intervals)", ""] + table(ratio_rows, True) + [""]
    summary = {}
    for r in ratio_rows:
        if "against_experiment" in r and r["source"].startswith("kerf"):
            summary.setdefault(r["against_experiment"], []).append(f"{r['trend']} ({r['source'][5:]})")
    md += ["## What the DEM reproduces", ""]
    for kind, label in (("agrees", "Agrees with the experiments"), ("differs", "Differs from them, resolved"),
                        ("not resolved", "Not resolved yet")):
        md.append(f"- {label}: {'; '.join(summary.get(kind, [])) or 'none'}.")
    moved = [r["trend"] for r in ratio_rows if r.get("domain_robust") == "differs"]
    md.append(f"- Moved by the domain (resolved): {'; '.join(moved) or 'none'}.")
    md += ["", "## Levels, per mm of width (reported, not acceptance)", ""] + table(level_rows, False) + [""]
    md += ["## The force as an edge part and a chip part (reported, not acceptance)", "",
           "Through the two depths of cut, F(h) = F0 + k h (Albrecht's decomposition): the depth-independent part "
           "F0 = 2 F(0.1) - F(0.2), the force of the edge, and the part per mm of depth k = (F(0.2) - F(0.1)) / "
           "0.1 mm, the chip's. With two depths any pair of forces splits so: the split reads the depth effect, it "
           "does not test that the force is linear in the depth (a force growing as the depth to a small power has "
           "the same two points). The large window spans the same millimetres at both depths; the default one twice "
           "as many at 0.2 mm, so its decomposition holds the window's growth too.", ""]
    md += table([r for r in rows if r["group"] == "decomposition"], True) + [""]
    md += damage_section(cuts, floors or {})
    md += cost_section(costs(cuts))
    md += resolve_section(pending or [])
    resolved, missing, shown = acceptance(rows, src.needs if src else None, src.thrust if src else frozenset(),
                                          pending or [])
    if shown:
        md.append("Shown, not asked: " + "; ".join(shown) + ".")
        md.append("")
    md.append(("**RESOLVED**: every verdict asked is resolved." if shown else
               "**RESOLVED**: every verdict above is resolved.") if resolved else
              "**NOT RESOLVED**: " + "; ".join(missing) + ".")
    return "\n".join(md) + "\n", resolved


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("records", nargs="*", metavar="RECORD",
                        help=f"records to merge (default {RECORD.relative_to(ROOT)}; --report takes one)")
    parser.add_argument("--experiments", default=str(EXPERIMENTS))
    parser.add_argument("--study", default=str(STUDY), help="the study of the record (the damage floors)")
    parser.add_argument("--out", default="out/seed000_trends")
    parser.add_argument("--report", action="store_true",
                        help="also write DIR/report.md, the steady validation case's report, and exit 1 while a "
                             "verdict asked is not resolved")
    args = parser.parse_args(argv)
    records = args.records or [str(RECORD)]
    if args.report and len(records) != 1:
        parser.error(f"--report: {len(records)} records given, expected one (the validation case's)")
    try:
        cuts = read_records(records)
    except ValueError as e:
        parser.error(str(e))
    floors = damage_floors(args.study)
    src = Sources(cuts, read_experiments(args.experiments), planned=set(floors) or None)
    all_trends = trends(src)
    rows = rows_of(all_trends)
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    write_csv(rows, out / "trends.csv")
    cost_rows = costs(cuts)
    with open(out / "cost.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(cost_rows[0]) if cost_rows else ["domain"])
        writer.writeheader()
        writer.writerows(cost_rows)
    plot(all_trends, out / "trends.png")
    plot_decomposition(all_trends, out / "decomposition.png")
    print("cuts per condition: " + ", ".join(f"{d}/{s}/{h} mm {len(v)}" for (d, s, h), v in sorted(cuts.items())))
    for r in rows:
        extra = f"  vs experiment: {r['against_experiment']}" if "against_experiment" in r else ""
        extra += f"  domain: {r['domain_robust']}" if "domain_robust" in r else ""
        print(f"{r['trend']:<58} {r['source']:<13} {r['value']:8.3g} [{r['ci95_low']:.3g}, {r['ci95_high']:.3g}]"
              f"{extra}")
    print(f"wrote {out / 'trends.csv'}, {out / 'cost.csv'}, {out / 'trends.png'}, {out / 'decomposition.png'}")
    if args.report:
        text, resolved = report(rows, cuts, records[0], floors, src, to_resolve(rows, all_trends, src, cost_rows))
        tmp = out / "report.md.tmp"
        tmp.write_text(text)
        tmp.replace(out / "report.md")
        print(f"wrote {out / 'report.md'}: {'RESOLVED' if resolved else 'NOT RESOLVED'}")
        return 0 if resolved else 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
