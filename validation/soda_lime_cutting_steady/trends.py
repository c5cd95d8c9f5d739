#!/usr/bin/env python3
"""The Yang et al. 2018 trends from a record of steady cuts (issue 41): does the DEM reproduce what the experiments
show, and is each trend the same in the two domains?

    PYTHONPATH=build/python python3 validation/soda_lime_cutting_steady/trends.py [RECORD.csv ...] [--out DIR]
        [--experiments CSV] [--study JSON] [--report]

(the module kerf from the build: its kerf.stats and kerf.records; scripts/validate.sh sets the path.)

RECORD (default data/studies/results/seed000_steady.csv) is the record that `kerf-dem study
data/studies/seed000_steady.json` writes, one row per cut: domain, surface (regular, rectangular, trapezoidal),
depth_of_cut_mm, seed, main_force_N, thrust_force_N, width_mm, ... Everything here comes from the record and the
experiments' table alone, so the numbers outlive the machine that ran the cuts. Several records merge (one model
choice's cuts spread over two studies); a cut in two of them is an error. The study that writes a record
(data/studies/X.json for data/studies/results/X.csv; its conditions are those expected, and give the damage floors) is
found from the record (studies_of; --study overrides it; a record without one takes seed000_steady.json's).

Model variants. A record may have model-choice columns (kerf.records.MODEL_CHOICES: edge_zone, layer_factor,
groove_damage_depth_um; a new one is one entry there): their values make a cut's variant ("zone off", "zone on", "zone
on, layer_factor 2.46"), and cuts are grouped by variant as well as by domain. Each variant is a kerf column of its
own beside the others ("kerf default, zone off" | "kerf default, zone on" | ..., trends.csv's source), with its own
verdicts against the experiments; default against large is compared within one variant; the damage and cost tables
(and cost.csv) get a variant column, the report's lists name the variant. A record without such columns is the one
unnamed variant ("kerf default"), reported as before. A cut is its variant, domain, surface, depth and packing: one in
two records is an error.
A grooves-only choice (kerf.records.GROOVES_ONLY_CHOICES: the grooves' laser-affected layer, groove_damage_depth_um)
leaves the regular surface as it is: its variant ("zone on, groove layer um 25") has grooved cuts only, and its regular
force is that of the variant without it ("zone on"), the same cuts, so its groove effect is against them.

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
DIR/trends.png (+ .pdf): each trend with both domains (and each variant: a colour each, the domain's marker), the
experiments and the paper's DEM, with their intervals; DIR/decomposition.png: each surface's force split through the
two depths of cut into an edge part and a chip part (Albrecht's decomposition, F = F0 + k h). With --report also
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

from kerf.records import (GROOVED, MODEL_CHOICES, per_width, read_experiments, read_records, reference,
                          regular_variant_of)
from kerf.result_keys import CutResults as R
from kerf.stats import combination, difference, mean_of, packings_factor, ratio, verdict

ROOT = pathlib.Path(__file__).resolve().parents[2]
RECORD = ROOT / "data/studies/results/seed000_steady.csv"
STUDY = ROOT / "data/studies/seed000_steady.json"
EXPERIMENTS = ROOT / "data/experiments/soda_lime_orthogonal_cutting.csv"
DOMAINS = ("default", "large")


def kerf_source(domain, variant=""):
    """The name of kerf's column of a domain and model variant: 'kerf default', 'kerf default, zone on'."""
    return f"kerf {domain}" + (f", {variant}" if variant else "")


def split_source(source):
    """(domain, variant) of a kerf column's name (kerf_source's); None for a reference's."""
    if not source.startswith("kerf "):
        return None
    domain, _, variant = source[5:].partition(", ")
    return domain, variant


def variant_key(variant):
    """The sort key of a variant's name: its words, numbers by value ('' first; 'layer_factor 2.46' before 10)."""
    key = []
    for word in variant.replace(",", " ").split():
        try:
            key.append((0, float(word), ""))
        except ValueError:
            key.append((1, 0.0, word))
    return key


def by_variant(cuts):
    """{variant: {(domain, surface, depth_mm): {seed: row}}} in variant_key's order: read_records(...,
    by_variant=True)'s as it is, read_record's plain {(domain, surface, depth_mm): ...} as the one unnamed
    variant ''."""
    cuts = {"": cuts} if any(isinstance(k, tuple) for k in cuts) else cuts
    return {v: cuts[v] for v in sorted(cuts, key=variant_key)}


def conditions_of(cuts):
    """[(variant, (domain, surface, depth_mm), {seed: row})] by condition, the variants of one condition together;
    and whether any variant is named (the tables then have a variant column)."""
    variants = by_variant(cuts)
    out = [(v, key, by_seed) for v, by_key in variants.items() for key, by_seed in by_key.items()]
    return sorted(out, key=lambda c: (c[1], variant_key(c[0]))), any(variants)


class Sources:
    """Per condition means of kerf (by model variant and domain) and of the references (experiment, paper_dem)."""

    def __init__(self, cuts, experiments, planned=None):
        """cuts: read_record's {(domain, surface, depth_mm): {seed: row}} (the one unnamed variant), or each model
        variant's, read_records(..., by_variant=True)'s {variant: those}. planned: the (domain, surface, depth_mm)
        conditions the study runs (None: every domain runs every condition), expected of every variant; a trend is
        expected in a domain only where the study runs all its conditions."""
        self.variants = by_variant(cuts) or {"": {}}
        self.experiments, self.planned = experiments, planned
        self.needs = {}  # trend name -> the domains expected to give it (filled by trends())
        self.conditions = {}  # trend name -> its [(surface, depth_mm)] (filled by trends())
        self.thrust = set()  # the trends of the thrust force (filled by trends())

    def domains_for(self, conditions):
        if self.planned is None:
            return DOMAINS
        return tuple(d for d in DOMAINS if all((d, s, h) in self.planned for s, h in conditions))

    def shown_domains(self):
        """The domains the report gives a column each: those the study runs (every one without a study), or with
        cuts."""
        if self.planned is None:
            return DOMAINS
        cut = {key[0] for by_key in self.variants.values() for key in by_key}
        return tuple(d for d in DOMAINS if d in cut or any(p[0] == d for p in self.planned))

    def columns(self):
        """kerf's columns (kerf_source's names), by domain, then variant."""
        return [kerf_source(d, v) for d in self.shown_domains() for v in self.variants]

    @staticmethod
    def variant_cutting(variant, surface):
        """The variant whose cuts of `surface` are `variant`'s: a grooves-only choice's variant cuts the regular
        surface as the variant without it (regular_variant_of)."""
        return regular_variant_of(variant) if surface == "regular" else variant

    def cuts(self, domain, surface, depth, variant=""):
        """{seed: row} of a variant's cuts of one condition."""
        return self.variants.get(self.variant_cutting(variant, surface), {}).get((domain, surface, depth), {})

    def kerf(self, domain, surface, depth, quantity, variant=""):
        rows = self.cuts(domain, surface, depth, variant).values()
        if quantity in ("main", "thrust"):
            return mean_of([per_width(r, quantity) for r in rows])
        return mean_of([r.get(quantity, math.nan) for r in rows])

    def reference(self, source, surface, depth, quantity):
        return reference(self.experiments, source, surface, depth, quantity)


def trends(src):
    """Every trend: (name, group, {source: Estimate}), sources 'kerf default', 'kerf large' (with a model variant:
    'kerf default, zone on', ...; kerf_source), 'experiment', 'paper DEM'; ratios of condition means (levels: the
    means themselves). make_kerf(at) is a trend of kerf's from at(surface, depth, quantity), one domain and variant's
    mean."""
    out = []

    def at_of(domain, variant):
        return lambda surface, depth, quantity: src.kerf(domain, surface, depth, quantity, variant)

    def add(name, group, conditions, make_kerf, make_ref, quantity=None):
        src.needs[name] = src.domains_for(conditions)
        src.conditions[name] = conditions
        if quantity == "thrust":
            src.thrust.add(name)
        values = {}
        for domain in DOMAINS:
            for variant in src.variants:
                e = make_kerf(at_of(domain, variant))
                if e is not None and math.isfinite(e.value):
                    values[kerf_source(domain, variant)] = e
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
                    lambda at, s=surface, d=depth, q=q: at(s, d, q),
                    lambda source, s=surface, d=depth, q=q: src.reference(source, s, d, q))
    for q in ("main", "thrust"):
        for surface in ("regular",) + GROOVED:
            add(f"depth effect {q}, {surface} (0.2 / 0.1 mm)", "ratio", [(surface, 0.2), (surface, 0.1)],
                lambda at, s=surface, q=q: ratio(at(s, 0.2, q), at(s, 0.1, q)),
                lambda source, s=surface, q=q: ref_ratio(source, (s, 0.2), (s, 0.1), q), q)
    for q in ("main", "thrust"):
        for surface in GROOVED:
            for depth in (0.1, 0.2):
                add(f"groove effect {q}, {surface} / regular at {depth} mm", "ratio",
                    [(surface, depth), ("regular", depth)],
                    lambda at, s=surface, d=depth, q=q: ratio(at(s, d, q), at("regular", d, q)),
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
                    lambda at, s=surface, q=q, c=c: through_depths(c, at(s, 0.1, q), at(s, 0.2, q)),
                    lambda source, s=surface, q=q, c=c: through_depths(c, src.reference(source, s, 0.1, q),
                                                                       src.reference(source, s, 0.2, q)))
    for depth in (0.1, 0.2):
        add(f"trapezoidal / rectangular thrust at {depth} mm", "ratio",
            [("trapezoidal", depth), ("rectangular", depth)],
            lambda at, d=depth: ratio(at("trapezoidal", d, "thrust"), at("rectangular", d, "thrust")), None,
            "thrust")
        # The damage as the subsurface cracks under the steady cut: their depth is censored in both domains
        # (damage_floors), their number within the domain is not.
        for surface in GROOVED:
            add(f"subsurface cracks under the steady cut, {surface} / regular at {depth} mm", "ratio",
                [(surface, depth), ("regular", depth)],
                lambda at, s=surface, d=depth: ratio(at(s, d, R.cracks_subsurface_steady),
                                                     at("regular", d, R.cracks_subsurface_steady)),
                None)
    return out


def study_of(record):
    """The study that writes `record`: <the record's folder>/../<its name>.json when that study's record.file is it
    (data/studies/results/X.csv: data/studies/X.json), else None."""
    record = pathlib.Path(record).resolve()
    study = record.parent.parent / f"{record.stem}.json"
    try:
        if (study.parent / json.loads(study.read_text())["record"]["file"]).resolve() == record:
            return study
    except (OSError, ValueError, KeyError, TypeError):
        pass
    return None


def studies_of(records):
    """The studies that write `records` (study_of), or STUDY where none is found."""
    return list(dict.fromkeys(s for s in map(study_of, records) if s)) or [STUDY]


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
    bound), which the crack-count trends above avoid. cuts: as Sources takes them (a variant column where one is
    named)."""
    conditions, named = conditions_of(cuts)
    md = ["## Damage depth under the steady cut (reported)", "",
          "| domain | surface | depth of cut (mm) |" + (" variant |" if named else "") + " packings | deepest crack "
          "below the cut line (um) | floor (um) | censored |", "|---|---|---:|" + ("---|" if named else "") +
          "---:|---:|---:|---:|"]
    censored_all = True
    for variant, key, by_seed in conditions:
        depths = [r.get(R.subsurface_damage_depth_steady_um, math.nan) for r in by_seed.values()]
        depths = [d for d in depths if isinstance(d, float) and math.isfinite(d)]
        if not depths or key not in floors:
            continue
        floor, diameter = floors[key]
        censored = sum(d >= floor - diameter for d in depths)
        censored_all = censored_all and censored == len(depths)
        md.append(f"| {key[0]} | {key[1]} | {key[2]:g} |" + (f" {variant} |" if named else "") +
                  f" {len(depths)} | {min(depths):.0f}-{max(depths):.0f} | {floor:.0f} | {censored} of {len(depths)} |")
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
    spread needs two), and their CPU-hours at the median cut. Rows without two packings have no spread and no n.
    cuts: as Sources takes them; with a named model variant each row has its variant (after the depth)."""
    out = []
    conditions, named = conditions_of(cuts)
    for variant, (domain, surface, depth), by_seed in conditions:
        rows = list(by_seed.values())
        cpu = [r["cpu_time_s"] for r in rows if isinstance(r.get("cpu_time_s"), float)]
        mains = [per_width(r, "main") for r in rows]
        row = {"domain": domain, "surface": surface, "depth_of_cut_mm": depth} | ({"variant": variant} if named else {})
        row |= {"cuts": len(rows), "cpu_s_per_cut": statistics.median(cpu) if cpu else math.nan,
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
    named = any("variant" in r for r in cost_rows)
    head = "| domain | surface | depth (mm) |" + (" variant |" if named else "") + \
        " cuts | CPU s per cut (median) | main force cv | " + " | ".join(
        f"packings, CPU-h for {e:.0%}" for e in COST_TARGETS) + " |"
    md = ["## What an answer costs", "",
          "CPU seconds are the record's (one thread, on the machine that ran the cut, under whatever load it "
          "had: an upper bound of a quiet core's). The packings a target standard error of the main force needs "
          "are (cv / target)^2 from the spread between the packings so far (itself uncertain with few packings).",
          "", head, "|---|---|---:|" + ("---|" if named else "") + "---:|---:|---:|" + "---:|" * len(COST_TARGETS)]
    for r in cost_rows:
        cv = f"{r['main_force_cv']:.2f}" if math.isfinite(r["main_force_cv"]) else "—"
        cells = [f"{r[f'packings_for_{e:.0%}']}, {r[f'cpu_h_for_{e:.0%}']:.1f}" if r[f"packings_for_{e:.0%}"]
                 else "—" for e in COST_TARGETS]
        md.append(f"| {r['domain']} | {r['surface']} | {r['depth_of_cut_mm']:g} |" +
                  (f" {r['variant']} |" if named else "") + f" {r['cuts']} | {r['cpu_s_per_cut']:.0f} | {cv} | " +
                  " | ".join(cells) + " |")
    return md + [""]


def against_experiments(trend, source):
    """The name of a verdict of `source` ('kerf default', ...) against the experiments (the report's, the acceptance's
    and to_resolve's)."""
    return f"{trend} ({source}) against the experiments"


def between_domains(trend, variant=""):
    """The name of a trend's domain-robustness verdict (within one model variant)."""
    return f"{trend}" + (f" ({variant})" if variant else "") + ": default against large domain"


def to_resolve(rows, all_trends, src, cost_rows):
    """Each of kerf's verdicts not resolved in `rows` (rows_of's; the acceptance's: ratios against the experiments,
    and default against large), with what resolving it would take at the present spread (packings_factor):
    [{verdict, packings now (per condition), factor, why, packings per condition, CPU-hours more}]. The CPU-hours are
    each condition's median cut times its added packings; two verdicts sharing a condition share its cuts (not summed
    here; a model variant's conditions are its own cuts)."""
    cpu = {(r.get("variant", ""), r["domain"], r["surface"], r["depth_of_cut_mm"]): r["cpu_s_per_cut"]
           for r in cost_rows}
    values_of = {name: values for name, _, values in all_trends}
    out = []

    def add(label, name, domains, variant, terms, against):
        k, why = packings_factor(terms, against)
        keys = [(dom, s, h) for dom in domains for s, h in src.conditions[name]]
        now = [len(src.cuts(*key, variant)) for key in keys]
        row = {"verdict": label, "now": now, "factor": k, "why": why}
        if math.isfinite(k):
            need = [math.ceil(k * n - 1e-9) for n in now]
            row["need"] = need
            row["cpu_h"] = sum((m - n) * cpu.get((src.variant_cutting(variant, key[1]),) + key, math.nan)
                               for m, n, key in zip(need, now, keys)) / 3600
        out.append(row)

    open_rows = [r for r in rows if r["group"] == "ratio" and r["source"].startswith("kerf")]
    for name in dict.fromkeys(r["trend"] for r in open_rows):
        values = values_of[name]
        for r in open_rows:  # against the experiments first, then between the domains
            if r["trend"] == name and r.get("against_experiment") == "not resolved":
                e, exp = values[r["source"]], values["experiment"]
                domain, variant = split_source(r["source"])
                add(against_experiments(name, r["source"]), name, (domain,), variant,
                    [(1.0, e, True), (-1.0, exp, False)], exp)
        for r in open_rows:
            if r["trend"] == name and r.get("domain_robust") == "not resolved":
                variant = split_source(r["source"])[1]
                default, large = values[kerf_source("default", variant)], values[kerf_source("large", variant)]
                add(between_domains(name, variant), name, DOMAINS, variant,
                    [(1.0, default, True), (-1.0, large, True)], large)
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
    domain, from the large one of the same model variant) with the verdicts."""
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
            kerf = split_source(source)
            large = kerf_source("large", kerf[1]) if kerf and kerf[0] == "default" else None
            if large in values:
                d = difference(e, values[large])
                row.update(default_minus_large=d.value, default_minus_large_low=d.low,
                           default_minus_large_high=d.high, domain_robust=verdict(d, values[large]))
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
VARIANT_COLOURS = ("tab:blue", "tab:red", "tab:purple", "tab:orange", "tab:cyan", "tab:brown", "tab:olive", "tab:pink")


def styles(all_trends):
    """{source: (marker, colour)} of the sources in all_trends, kerf's by domain then variant, then the references.
    The one unnamed variant: STYLE's; with named model variants the marker is the domain's and the colour the
    variant's (VARIANT_COLOURS)."""
    kerf = {s for _, _, values in all_trends for s in values if split_source(s)}
    variants = sorted({split_source(s)[1] for s in kerf}, key=variant_key) or [""]
    out = {}
    for domain in DOMAINS:
        for k, variant in enumerate(variants):
            source = kerf_source(domain, variant)
            if source in kerf or not any(variants):  # the unnamed variant: both domains, as STYLE
                marker, colour = STYLE[kerf_source(domain)]
                out[source] = (marker, VARIANT_COLOURS[k % len(VARIANT_COLOURS)] if any(variants) else colour)
    return out | {s: STYLE[s] for s in ("experiment", "paper DEM")}


def legend_columns(handles):
    """A legend's columns: one line for up to six entries, two lines beyond."""
    return len(handles) if len(handles) <= 6 else math.ceil(len(handles) / 2)


def offsets_of(sources, spacing):
    """Each source's vertical offset within a trend's row: `spacing` apart, less where many sources share it."""
    step = min(spacing, 0.8 / len(sources))
    return {s: (k - (len(sources) - 1) / 2) * step for k, s in enumerate(sources)}


def plot(all_trends, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    # Both on log axes (the paper's 2D DEM gives some 20 times the experiments' force per mm); an interval that
    # leaves the axis (unbounded, or below zero) is drawn to its edge.
    groups = [("level", "force per mm of width (N/mm, log scale)", (0.03, 30)),
              ("ratio", "ratio (log scale)", (0.03, 10))]
    heights = [sum(1 for _, g, _ in all_trends if g == group) for group, _, _ in groups]
    style = styles(all_trends)
    fig, axes = plt.subplots(1, 2, figsize=(15, 0.32 * max(1.0, len(style) / 4) * max(heights) + 2.2))
    for ax, (group, xlabel, (x_min, x_max)) in zip(axes, groups):
        items = [(n, v) for n, g, v in all_trends if g == group]
        offsets = offsets_of(list(style), 0.18)
        for y, (name, values) in enumerate(items):
            for source, e in values.items():
                marker, colour = style[source]
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
    handles = [plt.Line2D([], [], marker=m, color=c, ls="", label=s) for s, (m, c) in style.items()]
    domains = list(dict.fromkeys(split_source(s)[0] for _, _, v in all_trends for s in v if split_source(s)))
    where = f"in the {domains[0]} domain" if len(domains) == 1 else "in two domains"
    fig.suptitle(f"Yang et al. 2018 trends: kerf's steady cut {where} against the experiments and the paper's "
                 "DEM (95 % intervals; a bar at the axis' edge goes on beyond it)", y=0.99, fontsize=10)
    fig.legend(handles=handles, loc="upper center", ncol=legend_columns(handles), frameon=False,
               bbox_to_anchor=(0.5, 0.955))
    fig.tight_layout(rect=(0, 0, 1, 0.91))
    fig.savefig(path)
    fig.savefig(path.with_suffix(".pdf"))
    plt.close(fig)


def plot_decomposition(all_trends, path):
    """The main and thrust force's edge part and chip part per surface (linear axes), each source with its interval;
    the paper's DEM, some twenty times the experiments' force per mm, is left out."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    items = [(n, v) for n, g, v in all_trends if g == "decomposition"]
    if not items:
        return
    style = styles(all_trends)
    sources = [s for s in style if s != "paper DEM"]
    fig, axes = plt.subplots(1, 2, figsize=(13, 0.3 * max(1.0, len(sources) / 3) * len(items) + 2.4))
    offsets = offsets_of(sources, 0.22)
    for ax, kind, xlabel in ((axes[0], "depth-independent", "edge part F0 = 2 F(0.1) - F(0.2) (N/mm)"),
                             (axes[1], "per mm of depth", "chip part k = (F(0.2) - F(0.1)) / 0.1 mm (N/mm per mm)")):
        mine = [(n.replace(f" {kind}", "").split(" (")[0], v) for n, v in items if kind in n]
        for y, (_, values) in enumerate(mine):
            for source in sources:
                e = values.get(source)
                if e is None:
                    continue
                marker, colour = style[source]
                err = [[e.value - e.low], [e.high - e.value]] if e.resolved() else None
                ax.errorbar(e.value, y + offsets[source], xerr=err, fmt=marker, color=colour, ms=4, capsize=2, lw=1)
        ax.set_yticks(range(len(mine)))
        ax.set_yticklabels([n for n, _ in mine], fontsize=8)
        ax.invert_yaxis()
        ax.axvline(0, color="grey", lw=0.5)
        ax.set_xlabel(xlabel)
        ax.grid(axis="x", lw=0.3)
    handles = [plt.Line2D([], [], marker=style[s][0], color=style[s][1], ls="", label=s) for s in sources]
    fig.suptitle("The force through the two depths of cut, F(h) = F0 + k h: kerf's steady cut against the "
                 "experiments (95 % intervals; the default window spans twice the millimetres at 0.2 mm)", fontsize=10)
    fig.legend(handles=handles, loc="upper center", ncol=legend_columns(handles), frameon=False,
               bbox_to_anchor=(0.5, 0.94))
    fig.tight_layout(rect=(0, 0, 1, 0.88))
    fig.savefig(path)
    plt.close(fig)


def fmt_interval(value, low, high):
    """'0.64 [0.52, 0.77]'; '—' for a missing value, an open end for an unbounded interval."""
    if not isinstance(value, float) or not math.isfinite(value):
        return "—"
    if not (isinstance(low, float) and math.isfinite(low) and isinstance(high, float) and math.isfinite(high)):
        return f"{value:.3g} (no interval)"
    return f"{value:.3g} [{low:.3g}, {high:.3g}]"


def acceptance(rows, needs=None, thrust=frozenset(), pending=(), variants=("",)):
    """The steady case's acceptance (validation/soda_lime_cutting_steady/README.md): every trend compared with the
    experiments has a resolved verdict in each domain the study runs it in (needs: trend -> domains; default
    both), agrees or differs, and so has its domain robustness. Only kerf's verdicts are asked, and of those not
    the ones no number of kerf's packings can resolve: the paper's DEM's verdicts are shown beside, and so are the
    verdicts the experiments' own interval leaves open (pending, to_resolve's rows: why 'experiments'). The thrust's
    (trend names in `thrust`) are reported with whatever the packings reach (issue 41: the packings stop on the main
    force's standard error), not asked. Each model variant (variants) is asked for on its own. Returns (resolved,
    [what is not], [what is shown, not asked, and why])."""
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
            ask(between_domains(r["trend"], split_source(r["source"])[1]), r["trend"])
    ratios_with_experiment = {r["trend"] for r in rows if r["group"] == "ratio" and r["source"] == "experiment"}
    for trend in sorted(ratios_with_experiment):
        sources = {r["source"] for r in rows if r["trend"] == trend}
        for domain in (needs or {}).get(trend, DOMAINS):
            for variant in variants:
                if kerf_source(domain, variant) not in sources:
                    missing.append(f"{trend} ({kerf_source(domain, variant)}): no cuts")
    return not missing, missing, shown


def report(rows, cuts, record_path, floors=None, src=None, pending=None, studies=None):
    """The steady case's report.md: what is compared and why, the trends with their verdicts, the levels, and
    the acceptance line. Every verdict is the one rows_of drew from the intervals. record_path: the record, or a
    list of the records merged; cuts: as Sources takes them (each model variant a column of its own); studies: those
    that write the records (default: studies_of's)."""
    paths = [record_path] if isinstance(record_path, (str, pathlib.PurePath)) else list(record_path)

    def shown(path):
        path = pathlib.Path(path).resolve()
        return path.relative_to(ROOT) if path.is_relative_to(ROOT) else path

    names = [f"`{shown(path)}`" for path in paths]
    study_names = " and ".join(f"`kerf-dem study {shown(s)}`" for s in studies or studies_of(paths))
    command = "python3 validation/soda_lime_cutting_steady/trends.py" + \
        "".join(f" {shown(path)}" for path in paths if pathlib.Path(path).resolve() != RECORD) + " --report"
    variants = by_variant(cuts)
    every = [r for by_key in variants.values() for by_seed in by_key.values() for r in by_seed.values()]
    n_cuts = len(every)
    cpu_h = sum(r.get("cpu_time_s", 0.0) for r in every if isinstance(r.get("cpu_time_s"), float)) / 3600
    dates = [r.get("date") for r in every if isinstance(r.get("date"), str)]
    latest = f", the latest recorded {max(dates)}" if dates else ""
    md = ["# Validation: soda-lime glass, the Yang et al. 2018 trends in the steady cut", "",
          f"From the record{'s' if len(names) > 1 else ''} {', '.join(names)} alone ({n_cuts} cuts{latest}, "
          f"{cpu_h:.1f} CPU-hours; {study_names} add{'' if ' and ' in study_names else 's'} to "
          f"{'them' if len(names) > 1 else 'it'}, this report is `{command}`).",
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
    if any(variants):
        choices = [c for c, _ in MODEL_CHOICES if any(r.get(c, "") not in ("", None) for r in every)]
        whose = "The records'" if len(names) > 1 else "The record's"
        columns_make = f"columns ({', '.join(choices)}) make" if len(choices) > 1 else f"column ({choices[0]}) makes"
        md[-1:-1] = [f"- **Model variants.** {whose} model-choice {columns_make} {len(variants)} variants of the "
                     f"model: {'; '.join(variants)}. Each variant is a column of its own, with its own trends and "
                     "verdicts against the experiments; the two domains are compared within a variant. The columns "
                     "side by side compare the model choices."]
    ratio_rows = [r for r in rows if r["group"] == "ratio"]
    level_rows = [r for r in rows if r["group"] == "level"]
    columns = src.columns() if src else list(dict.fromkeys(
        [kerf_source(d) for d in DOMAINS] + [r["source"] for r in rows if split_source(r["source"])]))
    robust = [c for c in columns if split_source(c)[0] == "default" and
              kerf_source("large", split_source(c)[1]) in columns]

    def table(selected, with_verdicts):
        trends_in_order = list(dict.fromkeys(r["trend"] for r in selected))
        head = "| trend | " + " | ".join(columns) + " | experiment | paper's DEM |"
        rule = "|---|" + "---:|" * (len(columns) + 2)
        if with_verdicts:
            head += " " + " | ".join([f"{c[5:]} vs experiment" for c in columns] +
                                     ["default - large" + c[len("kerf default"):] for c in robust]) + " |"
            rule += "---|" * (len(columns) + len(robust))
        out = [head, rule]
        for trend in trends_in_order:
            by = {r["source"]: r for r in selected if r["trend"] == trend}
            cell = lambda s: fmt_interval(by[s]["value"], by[s]["ci95_low"], by[s]["ci95_high"]) if s in by else "—"
            line = "| " + " | ".join([trend] + [cell(s) for s in columns + ["experiment", "paper DEM"]]) + " |"
            if with_verdicts:
                verdict = lambda s, k: by[s].get(k, "—") if s in by else "—"
                line += " " + " | ".join([verdict(s, "against_experiment") for s in columns] +
                                         [verdict(s, "domain_robust") for s in robust]) + " |"
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
    moved = [r["trend"] + (f" ({split_source(r['source'])[1]})" if split_source(r["source"])[1] else "")
             for r in ratio_rows if r.get("domain_robust") == "differs"]
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
                                          pending or [], list(src.variants) if src else ("",))
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
                        help=f"records to merge (default {RECORD.relative_to(ROOT)})")
    parser.add_argument("--experiments", default=str(EXPERIMENTS))
    parser.add_argument("--study", help="the study of the record (the damage floors, the conditions it runs; default: "
                                        "the records' own, studies_of, else " f"{STUDY.relative_to(ROOT)})")
    parser.add_argument("--out", default="out/seed000_trends")
    parser.add_argument("--report", action="store_true",
                        help="also write DIR/report.md, the steady validation case's report, and exit 1 while a "
                             "verdict asked is not resolved")
    args = parser.parse_args(argv)
    records = args.records or [str(RECORD)]
    try:
        cuts = read_records(records, by_variant=True)
    except ValueError as e:
        parser.error(str(e))
    floors = {}
    studies = [args.study] if args.study else studies_of(records)
    for study in studies:
        floors |= damage_floors(study)
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
    print("cuts per condition: " + ", ".join(f"{d}/{s}/{h} mm{f' ({v})' if v else ''} {len(c)}"
                                             for v, (d, s, h), c in conditions_of(cuts)[0]))
    width = max([13] + [len(r["source"]) + 1 for r in rows])
    for r in rows:
        extra = f"  vs experiment: {r['against_experiment']}" if "against_experiment" in r else ""
        extra += f"  domain: {r['domain_robust']}" if "domain_robust" in r else ""
        print(f"{r['trend']:<58} {r['source']:<{width}} {r['value']:8.3g} [{r['ci95_low']:.3g}, {r['ci95_high']:.3g}]"
              f"{extra}")
    print(f"wrote {out / 'trends.csv'}, {out / 'cost.csv'}, {out / 'trends.png'}, {out / 'decomposition.png'}")
    if args.report:
        text, resolved = report(rows, cuts, records, floors, src, to_resolve(rows, all_trends, src, cost_rows),
                                studies)
        tmp = out / "report.md.tmp"
        tmp.write_text(text)
        tmp.replace(out / "report.md")
        print(f"wrote {out / 'report.md'}: {'RESOLVED' if resolved else 'NOT RESOLVED'}")
        return 0 if resolved else 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
