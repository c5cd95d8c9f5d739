#!/usr/bin/env python3
"""A study of cuts with and without the edge zone (issue 54; data/studies/issue54_zone_pilot.json): per surface and
zone, the mean over the packings of the cutting and thrust force per mm of width, the share of the steady samples in
which the zone met intact glass, the tied share of the glass behind the tool in the first 25 um below the cut line
and the subsurface damage depth, each with its 95 % interval (Student t over the packings); then the groove effect
(rectangular / regular, Fieller's interval) with the zone and without it, and the zone's effect (on / off) on each
surface. Reads the record alone.

    PYTHONPATH=build/python python3 analysis/edge_zone_pilot.py data/studies/results/issue54_zone_pilot.csv
"""
import csv
import math
import sys

from kerf.stats import mean_of, ratio

QUANTITIES = [("cutting_force_N_per_mm", "cutting N/mm"), ("thrust_force_N_per_mm", "thrust N/mm"),
              ("edge_zone_intact_share_steady", "zone met intact"),
              ("tied_share_behind_depth_0_25_um_steady", "tied behind 0-25 um"),
              ("subsurface_damage_depth_steady_um", "damage um")]


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
    for force in ("cutting_force_N_per_mm", "thrust_force_N_per_mm"):
        for zone in ("off", "on"):
            if ("rectangular", zone) in groups and ("regular", zone) in groups:
                r = ratio(estimate(groups[("rectangular", zone)], force), estimate(groups[("regular", zone)], force))
                lines.append(f"groove effect (rectangular / regular), {force}, zone {zone}: {interval(r)}")
        for surface in ("regular", "rectangular"):
            if (surface, "on") in groups and (surface, "off") in groups:
                r = ratio(estimate(groups[(surface, "on")], force), estimate(groups[(surface, "off")], force))
                lines.append(f"zone effect (on / off), {force}, {surface}: {interval(r)}")
    return "\n".join(lines)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    print(report(read(sys.argv[1])))
