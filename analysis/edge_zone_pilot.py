#!/usr/bin/env python3
"""A study of cuts with and without the edge zone (issue 54; data/studies/issue54_zone_pilot.json): per surface and
zone, the mean over the packings of the cutting and thrust force per mm of width, the share of the steady samples in
which the zone met intact glass, the tied share of the glass behind the tool in the first 25 um below the cut line
and the subsurface damage depth, each with its 95 % interval (Student t over the packings); then the groove effect
(rectangular / regular, Fieller's interval) with the zone and without it, and the zone's effect (on / off) on each
surface. Reads the record alone. Given a second record of the same conditions at twice the depth of cut
(data/studies/issue54_zone_pilot_02.json), also each surface's force split through the two depths, F = F0 + k h:
F0 = 2 F(h) - F(2h), k = (F(2h) - F(h)) / h, and the depth effect F(2h) / F(h). Given with --against a record of
the same conditions and packings with one change (another glass: data/studies/issue54_weibull_pilot.json against the
zone pilot), the change's effect on each quantity, paired by packing: the mean of the per-packing differences (this
record less the other) with its 95 % interval. Given with --beside a record of the same conditions on other packings
(another specimen: data/studies/issue54_fine_band_reference.json, fine disks at the cut line, beside the zone pilot),
each of its groups against each group of the other record on the same surface, unpaired: the difference of the
means (this record less the other) with its Welch 95 % interval.

    PYTHONPATH=build/python python3 analysis/edge_zone_pilot.py data/studies/results/issue54_zone_pilot.csv \
        [data/studies/results/issue54_zone_pilot_02.csv]
    PYTHONPATH=build/python python3 analysis/edge_zone_pilot.py data/studies/results/issue54_weibull_pilot.csv \
        --against data/studies/results/issue54_zone_pilot.csv
    PYTHONPATH=build/python python3 analysis/edge_zone_pilot.py data/studies/results/issue54_fine_band_reference.csv \
        --beside data/studies/results/issue54_zone_pilot.csv
"""
import csv
import math
import sys

from kerf.result_keys import CutResults as R
from kerf.stats import combination, difference, mean_of, ratio

QUANTITIES = [(R.cutting_force_N_per_mm, "cutting N/mm"), (R.thrust_force_N_per_mm, "thrust N/mm"),
              (R.edge_zone_intact_share_steady, "zone met intact"),
              (R.tied_share_behind_depth_0_25_um_steady, "tied behind 0-25 um"),
              (R.subsurface_damage_depth_steady_um, "damage um"),
              (R.edge_touches_tied_share_steady, "edge touched tied")]


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan


def read(path):
    """{(surface, edge_zone): [row, ...]} of the record's rows."""
    groups = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            groups.setdefault((row["surface"], row["edge_zone"]), []).append(row)
    return groups


def estimate(rows, key):
    return mean_of([number(r.get(key)) for r in rows])


def interval(e, digits=3):
    if not math.isfinite(e.value):
        return "-"
    if math.isinf(e.low) or math.isinf(e.high):
        return f"{e.value:.{digits}g} (unbounded: the denominator is not resolved from zero)"
    if not e.resolved():
        return f"{e.value:.{digits}g} (n = {e.n})"
    return f"{e.value:.{digits}g} [{e.low:.{digits}g}, {e.high:.{digits}g}]"


def report(groups):
    lines = ["| surface | zone | packings | " + " | ".join(label for _, label in QUANTITIES) + " |",
             "|---|---|---|" + "---|" * len(QUANTITIES)]
    for (surface, zone), rows in sorted(groups.items()):
        cells = [interval(estimate(rows, key)) for key, _ in QUANTITIES]
        lines.append(f"| {surface} | {zone} | {len(rows)} | " + " | ".join(cells) + " |")
    lines.append("")
    for force in (R.cutting_force_N_per_mm, R.thrust_force_N_per_mm):
        for zone in ("off", "on"):
            if ("rectangular", zone) in groups and ("regular", zone) in groups:
                r = ratio(estimate(groups[("rectangular", zone)], force), estimate(groups[("regular", zone)], force))
                lines.append(f"groove effect (rectangular / regular), {force}, zone {zone}: {interval(r)}")
        for surface in ("regular", "rectangular"):
            if (surface, "on") in groups and (surface, "off") in groups:
                r = ratio(estimate(groups[(surface, "on")], force), estimate(groups[(surface, "off")], force))
                lines.append(f"zone effect (on / off), {force}, {surface}: {interval(r)}")
    return "\n".join(lines)


def split(shallow, deep, h_mm):
    """Each (surface, zone) in both records: the force split through depths h and 2 h (independent packings)."""
    lines = []
    for key in sorted(set(shallow) & set(deep)):
        for force in (R.cutting_force_N_per_mm, R.thrust_force_N_per_mm):
            f1, f2 = estimate(shallow[key], force), estimate(deep[key], force)
            f0 = combination([(2.0, f1), (-1.0, f2)])
            k = combination([(1.0 / h_mm, f2), (-1.0 / h_mm, f1)])
            lines.append(f"{key[0]}, zone {key[1]}, {force}: at {h_mm:g} mm {interval(f1)}, at {2 * h_mm:g} mm "
                         f"{interval(f2)}; depth effect {interval(ratio(f2, f1))}; F0 {interval(f0)} N/mm; "
                         f"k {interval(k)} N/mm per mm")
    return "\n".join(lines)


def paired(changed, baseline):
    """Each (surface, zone) in both records: per quantity, the mean over the packings present in both (by seed) of
    the difference changed - baseline."""
    lines = ["| surface | zone | pairs | " + " | ".join(f"change in {label}" for _, label in QUANTITIES) + " |",
             "|---|---|---|" + "---|" * len(QUANTITIES)]
    for key in sorted(set(changed) & set(baseline)):
        base = {r["seed"]: r for r in baseline[key]}
        pairs = [(r, base[r["seed"]]) for r in changed[key] if r["seed"] in base]
        cells = [interval(mean_of([number(a.get(q)) - number(b.get(q)) for a, b in pairs])) for q, _ in QUANTITIES]
        lines.append(f"| {key[0]} | {key[1]} | {len(pairs)} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def beside(other, base):
    """Each group of `other` against each group of `base` on the same surface (independent packings): per quantity,
    the difference of the means, other - base."""
    lines = ["| surface | zone | against zone | packings | " +
             " | ".join(f"change in {label}" for _, label in QUANTITIES) + " |",
             "|---|---|---|---|" + "---|" * len(QUANTITIES)]
    for (surface, zone), rows in sorted(other.items()):
        for (base_surface, base_zone), base_rows in sorted(base.items()):
            if base_surface != surface:
                continue
            cells = [interval(difference(estimate(rows, q), estimate(base_rows, q))) for q, _ in QUANTITIES]
            lines.append(f"| {surface} | {zone} | {base_zone} | {len(rows)}, {len(base_rows)} | " + " | ".join(cells) +
                         " |")
    return "\n".join(lines)


def depth_of(path):
    with open(path, newline="") as f:
        return float(next(csv.DictReader(f))["depth_of_cut_mm"])


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[2] == "--against":
        print(report(read(sys.argv[1])))
        print()
        print(paired(read(sys.argv[1]), read(sys.argv[3])))
        sys.exit(0)
    if len(sys.argv) == 4 and sys.argv[2] == "--beside":
        print(report(read(sys.argv[1])))
        print()
        print(beside(read(sys.argv[1]), read(sys.argv[3])))
        sys.exit(0)
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    print(report(read(sys.argv[1])))
    if len(sys.argv) == 3:
        print()
        print(split(read(sys.argv[1]), read(sys.argv[2]), depth_of(sys.argv[1])))
