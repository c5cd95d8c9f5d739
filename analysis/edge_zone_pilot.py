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
means (this record less the other) with its Welch 95 % interval. With --by TAG a tag that varies within a surface
(data/studies/issue54_groove_damage_zone.json: the grooves' laser-affected layer) splits the surface's rows into
groups named "rectangular, TAG=value", each compared as its surface is (the groove effect against the regular group
of the same tags where there is one, data/studies/issue54_lateral_crack_ahead.json's lengths, else against the regular
surface; --against paired with the surface's rows of the other record); with --with RECORD the rows of another record
of the same conditions and packings join this record's (that study's regular cuts are issue54_cut_line_joints.json's).

    PYTHONPATH=build/python python3 analysis/edge_zone_pilot.py data/studies/results/issue54_zone_pilot.csv \
        [data/studies/results/issue54_zone_pilot_02.csv]
    PYTHONPATH=build/python python3 analysis/edge_zone_pilot.py data/studies/results/issue54_weibull_pilot.csv \
        --against data/studies/results/issue54_zone_pilot.csv
    PYTHONPATH=build/python python3 analysis/edge_zone_pilot.py data/studies/results/issue54_fine_band_reference.csv \
        --beside data/studies/results/issue54_zone_pilot.csv
    PYTHONPATH=build/python python3 analysis/edge_zone_pilot.py data/studies/results/issue54_groove_damage_zone.csv \
        --by groove_damage_depth_um --with data/studies/results/issue54_cut_line_joints.csv \
        --against data/studies/results/issue54_cut_line_joints.csv
"""
import argparse
import csv
import math

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


def read(path, by=(), groups=None):
    """{(surface, edge_zone): [row, ...]} of the record's rows, added to `groups` if given; a surface named with the
    value of each tag of `by` that a row has ("rectangular, groove_damage_depth_um=50")."""
    groups = {} if groups is None else groups
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            surface = ", ".join([row["surface"]] + [f"{t}={row[t]}" for t in by if row.get(t)])
            groups.setdefault((surface, row["edge_zone"]), []).append(row)
    return groups


def plain(surface):
    """The surface of a group's name without its tags."""
    return surface.split(",")[0]


def regular_of(surface, zone, groups):
    """The regular group a grooved group's groove effect divides by: the one with the same tags where the record has it
    (a model choice on both surfaces: the lateral crack's length), else the plain regular surface (a grooves-only
    choice: the grooves' laser-affected layer)."""
    same = "regular" + surface[len(plain(surface)):]
    return same if (same, zone) in groups else "regular"


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
    surfaces = sorted({surface for surface, _ in groups}, key=lambda s: (s != "regular", s))  # regular first
    for force in (R.cutting_force_N_per_mm, R.thrust_force_N_per_mm):
        for zone in ("off", "on"):
            for surface in (s for s in surfaces if plain(s) == "rectangular"):
                regular = regular_of(surface, zone, groups)
                if (surface, zone) in groups and (regular, zone) in groups:
                    r = ratio(estimate(groups[(surface, zone)], force), estimate(groups[(regular, zone)], force))
                    lines.append(f"groove effect ({surface} / {regular}), {force}, zone {zone}: {interval(r)}")
        for surface in surfaces:
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
    """Each (surface, zone) of `changed` whose surface, or its plain surface, `baseline` has: per quantity, the mean
    over the packings present in both (by seed) of the difference changed - baseline."""
    lines = ["| surface | zone | pairs | " + " | ".join(f"change in {label}" for _, label in QUANTITIES) + " |",
             "|---|---|---|" + "---|" * len(QUANTITIES)]
    for key in sorted(changed):
        base_key = key if key in baseline else (plain(key[0]), key[1])
        if base_key not in baseline:
            continue
        base = {r["seed"]: r for r in baseline[base_key]}
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
            if plain(base_surface) != plain(surface):
                continue
            cells = [interval(difference(estimate(rows, q), estimate(base_rows, q))) for q, _ in QUANTITIES]
            lines.append(f"| {surface} | {zone} | {base_zone} | {len(rows)}, {len(base_rows)} | " + " | ".join(cells) +
                         " |")
    return "\n".join(lines)


def depth_of(path):
    with open(path, newline="") as f:
        return float(next(csv.DictReader(f))["depth_of_cut_mm"])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("record")
    parser.add_argument("deeper", nargs="?", help="the same conditions at twice the depth of cut")
    parser.add_argument("--against", help="a record of the same conditions and packings with one change (paired)")
    parser.add_argument("--beside", help="a record of the same conditions on other packings (unpaired)")
    parser.add_argument("--by", action="append", default=[], help="a tag that splits a surface's rows into groups")
    parser.add_argument("--with", dest="also", action="append", default=[],
                        help="a record of the same conditions and packings whose rows join the record's")
    args = parser.parse_args()
    own = read(args.record, args.by)
    groups = {key: list(rows) for key, rows in own.items()}
    for path in args.also:
        read(path, args.by, groups)
    print(report(groups))
    if args.against:
        print()
        print(paired(own, read(args.against, args.by)))  # the record's own cuts, not those --with joined
    if args.beside:
        print()
        print(beside(groups, read(args.beside, args.by)))
    if args.deeper:
        print()
        print(split(groups, read(args.deeper, args.by), depth_of(args.record)))


if __name__ == "__main__":
    main()
