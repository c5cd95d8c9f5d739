#!/usr/bin/env python3
"""Steady cuts of two glasses on the same packings (issue 41 item 4): what one model choice changes in a cut.

    python3 analysis/paired_glasses.py BASE.csv OTHER.csv [--domain default] [--depth 0.1]
                                    [--base-domain large] [--base-depth 0.2]

BASE and OTHER are records of `kerf-dem study` (data/studies/results/*.csv with the columns of the Yang et al. 2018
study: domain, surface, depth_of_cut_mm, seed, main_force_N, thrust_force_N, ...), e.g. seed000_steady.csv and
seed000_softening_pairs.csv. Cuts pair by (domain, surface, depth, seed): a packing does not depend on the material. --base-domain and --base-depth
pair OTHER's cuts in --domain at --depth with BASE's in another domain or at another depth, packing by packing (the
same seed is the same packing in every window and at every depth): how the window or the depth moves one glass's cut,
e.g. BASE = OTHER = one record, --domain large --base-domain default.
Per surface: each glass's mean over the paired packings, and the paired ratio OTHER / BASE (the mean of the per-packing
ratios, Student t on n - 1 degrees of freedom). Then each glass's groove effect (grooved / regular, Fieller's
interval as in validation/soda_lime_cutting_steady/trends.py) and its change (delta method), against the experiments'
0.152 at 0.1 mm.
"""
import argparse
import math
import pathlib
import statistics

from kerf.records import per_width, read_record
from kerf.result_keys import CutResults as R
from kerf.stats import difference, mean_of, ratio

QUANTITIES = [(R.main_force_N, "main force (N/mm)"), (R.thrust_force_N, "thrust force (N/mm)"),
              (R.cracks_subsurface_steady, "subsurface cracks"),
              (R.subsurface_damage_depth_steady_um, "deepest subsurface crack (um)"),
              (R.contact_share_steady, "share in contact")]


def paired(base, other, key, quantity, base_key=None):
    """Seeds both records have for this condition (BASE's in base_key where given) and this quantity (a record may not
    keep it), and their values."""
    b, o = base.get(base_key or key, {}), other.get(key, {})
    seeds = sorted(s for s in set(b) & set(o) if quantity in b[s] and quantity in o[s])
    value = (lambda r: per_width(r, quantity[:-8])) if quantity.endswith("_force_N") else (lambda r: r[quantity])
    return seeds, [value(b[s]) for s in seeds], [value(o[s]) for s in seeds]


def paired_ratio(xs, ys):
    """Mean of y / x over the pairs with its 95 % interval (Student t on n - 1)."""
    return mean_of([y / x for x, y in zip(xs, ys)])


def compare(base, other, domain, depth, base_domain=None, base_depth=None):
    """The paired comparison's text: OTHER's cuts in domain at depth against BASE's in base_domain at base_depth (by
    default the same)."""
    base_domain = domain if base_domain is None else base_domain
    base_depth = depth if base_depth is None else base_depth
    lines = []
    if (base_domain, base_depth) != (domain, depth):
        lines.append(f"other: {domain} window, {depth:g} mm; base: {base_domain} window, {base_depth:g} mm")
    surfaces = sorted({k[1] for k in other if k[0] == domain and math.isclose(k[2], depth)})

    def pairs(surface, quantity):
        return paired(base, other, (domain, surface, depth), quantity, (base_domain, surface, base_depth))

    for quantity, label in QUANTITIES:
        lines.append(f"{label}:")
        for surface in surfaces:
            seeds, xs, ys = pairs(surface, quantity)
            if not seeds:
                continue
            r = paired_ratio(xs, ys)
            lines.append(f"  {surface:12s} seeds {seeds}: base {statistics.fmean(xs):.4g}, other {statistics.fmean(ys):.4g}, "
                         f"other / base {r.value:.3f} [{r.low:.3f}, {r.high:.3f}]")
    for quantity in (R.main_force_N, R.thrust_force_N):
        _, base_g, other_g = pairs("rectangular", quantity)
        _, base_r, other_r = pairs("regular", quantity)
        if len(base_g) < 2 or len(base_r) < 2:
            lines.append(f"groove effect {quantity[:-8]}: fewer than two paired packings of each surface")
            continue
        effects = {name: ratio(mean_of(g), mean_of(r))
                   for name, g, r in (("base", base_g, base_r), ("other", other_g, other_r))}
        d = difference(effects["other"], effects["base"])
        lines.append(f"groove effect {quantity[:-8]} (rectangular / regular, paired packings): base "
                     f"{effects['base'].value:.3f} [{effects['base'].low:.3f}, {effects['base'].high:.3f}], other "
                     f"{effects['other'].value:.3f} [{effects['other'].low:.3f}, {effects['other'].high:.3f}]; "
                     f"change {d.value:+.3f} [{d.low:+.3f}, {d.high:+.3f}]")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("base", type=pathlib.Path)
    ap.add_argument("other", type=pathlib.Path)
    ap.add_argument("--domain", default="default")
    ap.add_argument("--depth", default=0.1, type=float)
    ap.add_argument("--base-domain", help="BASE's window (default: --domain)")
    ap.add_argument("--base-depth", type=float, help="BASE's depth of cut in mm (default: --depth)")
    args = ap.parse_args()
    try:
        base, other = read_record(args.base), read_record(args.other)
    except ValueError as e:
        ap.error(str(e))
    print(compare(base, other, args.domain, args.depth, args.base_domain, args.base_depth))


if __name__ == "__main__":
    main()
