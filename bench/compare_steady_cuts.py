#!/usr/bin/env python3
"""Two sets of steady cuts compared packing by packing (e.g. data/studies/steady_window_undamped.json against the
same seeds of data/studies/steady_speed_undamped.json): the items of each study directory are matched by tool
speed and packing seed, and for the main and thrust forces the script prints both means with the cuts' own
errors (sqrt(sum sem^2) / n), the difference with that error and with the spread of the paired differences
(std / sqrt(n)), and the mean active-window disks (a cut without a window: the workpiece's), steady damage
depth (with the window's floor), steady subsurface cracks and wall time of each set, and, from each item's
forces.csv over the steady part, the share of samples with the tool in contact (main force > 0), the mean main
force while in contact and the main force's 99th percentile.

    python3 bench/compare_steady_cuts.py BASE_STUDY_DIR[:C] OTHER_STUDY_DIR[:C]

A directory followed by :C takes only its condition C's items (a study with several conditions at one speed);
a suffix @A-B only the packing seeds A to B.
"""
import csv
import json
import math
import pathlib
import statistics
import sys


def item_dirs(spec):
    """The finished items of STUDY_DIR, or of its condition C for STUDY_DIR:C, in name order; a suffix @A-B keeps
    only the packing seeds A to B (STUDY_DIR@1-4, STUDY_DIR:2@1-4)."""
    spec, seeds = spec.rsplit("@", 1) if "@" in spec else (spec, None)
    study_dir, condition = spec.rsplit(":", 1) if ":" in spec else (spec, "*")
    found = sorted((pathlib.Path(study_dir) / "items").glob(f"condition_{condition}_seed_*"))
    if seeds is None:
        return found
    first, last = (int(v) for v in seeds.split("-", 1))
    return [d for d in found if first <= int(d.name.rsplit("_", 1)[1]) <= last]


def items(spec):
    out = {}
    for item_dir in item_dirs(spec):
        s = json.loads((item_dir / "summary.json").read_text())
        s["item_dir"] = item_dir
        out[(s["cut"]["cut"]["speed_m_per_s"], s["study_item"]["seed"])] = s
    return out


def own_error(study, pairs, force):
    """The standard error of the mean force over the packings `pairs` from the cuts' own errors: sqrt(sum sem^2) / n."""
    return math.sqrt(sum(study[p]["results"][f"{force}_force_sem_N"] ** 2 for p in pairs)) / len(pairs)


def contact_statistics(item_dir, steady_from_mm):
    """Share of the steady samples with a main force > 0, mean main force over them, and its 99th percentile."""
    with open(item_dir / "forces.csv", newline="") as f:
        main = [float(r["main_force_N"]) for r in csv.DictReader(f) if float(r["tool_travel_mm"]) >= steady_from_mm]
    touching = [x for x in main if x > 0]
    p99 = sorted(main)[min(len(main) - 1, int(0.99 * len(main)))]
    return len(touching) / len(main), statistics.mean(touching) if touching else 0.0, p99


def window_of(s):
    """Mean disks integrated and the window's floor (um below the cut line; none without a window)."""
    w = s.get("active_window")
    return (w["mean_window_particles"], w["damage_depth_limit_um"]) if w else (s["n_particles"], math.nan)


def main():
    base, other = items(sys.argv[1]), items(sys.argv[2])
    pairs = sorted(set(base) & set(other))
    if not pairs:
        sys.exit("no packing (speed, seed) in both studies")
    print(f"{len(pairs)} packings in both: " + ", ".join(f"{v:g} m/s seed {k}" for v, k in pairs))
    n = len(pairs)
    for force in ("main", "thrust"):
        b = [base[p]["results"][f"{force}_force_N"] for p in pairs]
        o = [other[p]["results"][f"{force}_force_N"] for p in pairs]
        b_se, o_se = own_error(base, pairs, force), own_error(other, pairs, force)
        diff = statistics.mean(o) - statistics.mean(b)
        paired = statistics.stdev(x - y for x, y in zip(o, b)) / math.sqrt(n) if n > 1 else float("nan")
        print(f"{force}: base {statistics.mean(b):.3f} +- {b_se:.3f} N, other {statistics.mean(o):.3f} +- {o_se:.3f} N; "
              f"other - base {diff:+.3f} N (+- {math.hypot(b_se, o_se):.3f} by the cuts' own errors, +- {paired:.3f} by "
              f"the paired spread), {100 * diff / statistics.mean(b):+.0f} % +- {100 * math.hypot(b_se, o_se) / statistics.mean(b):.0f} %")
    for name, study in (("base", base), ("other", other)):
        mean = lambda f: statistics.mean(f(study[p]) for p in pairs)  # noqa: E731
        contact = {p: contact_statistics(study[p]["item_dir"], study[p]["results"]["steady_from_travel_mm"]) for p in pairs}
        print(f"{name}: {mean(lambda s: window_of(s)[0]):.0f} disks integrated, steady damage "
              f"depth {mean(lambda s: s['results']['subsurface_damage_depth_steady_um']):.0f} um (window floor "
              f"{mean(lambda s: window_of(s)[1]):.0f} um), "
              f"{mean(lambda s: s['results']['cracks_subsurface_steady']):.0f} steady subsurface cracks, "
              f"{mean(lambda s: s['study_item']['wall_time_s']):.0f} s per cut; tool in contact in "
              f"{100 * statistics.mean(c[0] for c in contact.values()):.1f} % of the steady samples, main force "
              f"{statistics.mean(c[1] for c in contact.values()):.2f} N while in contact, 99th percentile "
              f"{statistics.mean(c[2] for c in contact.values()):.2f} N")


if __name__ == "__main__":
    main()
