#!/usr/bin/env python3
"""Two sets of steady cuts compared packing by packing (e.g. data/studies/steady_window_undamped.json against the
same seeds of data/studies/steady_speed_undamped.json): the cuts of each set are matched by tool speed and packing
seed, and for the main and thrust forces the script prints both means with the cuts' own errors
(sqrt(sum sem^2) / n), the difference with that error and with the spread of the paired differences
(std / sqrt(n), and its Student-t 95 % interval), and the mean active-window disks (a cut without a window:
the workpiece's), steady damage depth (with the window's floor), steady subsurface cracks and wall time of each
set, and, from each cut's forces.csv over the steady part, the share of samples with the tool in contact (main
force > 0), the mean main force while in contact and the main force's 99th percentile.

    python3 analysis/compare_steady_cuts.py BASE[:C][@A-B] OTHER[:C][@A-B]
    python3 analysis/compare_steady_cuts.py record STUDY_DIR OUT.csv

A set is a study directory (its finished items) or a record file written by `record`: one row per cut with the
numbers above, so that a study's results outlive its item directories (data/studies/results/). :C takes only
condition C's cuts (a study with several conditions at one speed); @A-B only the packing seeds A to B.
"""
import csv
import math
import os
import pathlib
import statistics
import sys

from kerf.records import RECORD_FIELDS, item_dirs, read_set, record_of
from kerf.result_keys import CutResults as R
from kerf.stats import known_mean, own_error, t95


def write_records(study_dir, out):
    """Every finished item of STUDY_DIR as a record file, written whole or not at all."""
    rows = [record_of(d) for d in item_dirs(str(study_dir))]
    if not rows:
        sys.exit(f"no finished item in {study_dir}")
    tmp = pathlib.Path(f"{out}.tmp{os.getpid()}")
    with open(tmp, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=RECORD_FIELDS, lineterminator="\n")
        writer.writeheader()
        for r in sorted(rows, key=lambda r: (r["condition"], r["seed"])):
            writer.writerow({k: "" if isinstance(v, float) and math.isnan(v) else
                             f"{v:.6g}" if isinstance(v, float) else v for k, v in r.items()})
    tmp.replace(out)
    print(f"{out}: {len(rows)} cuts")


def compare(base, other):
    pairs = sorted(set(base) & set(other))
    if not pairs:
        sys.exit("no packing (speed, seed) in both sets")
    print(f"{len(pairs)} packings in both: " + ", ".join(f"{v:g} m/s seed {k}" for v, k in pairs))
    for force in ("main", "thrust"):
        key = f"{force}_force_N"
        known = [p for p in pairs if math.isfinite(base[p][key]) and math.isfinite(other[p][key])]
        if not known:
            print(f"{force}: not recorded")
            continue
        n = len(known)
        b, o = [base[p][key] for p in known], [other[p][key] for p in known]
        b_se, o_se = own_error(base, known, force), own_error(other, known, force)
        diff = statistics.mean(o) - statistics.mean(b)
        paired = statistics.stdev(x - y for x, y in zip(o, b)) / math.sqrt(n) if n > 1 else math.nan
        half = t95(n - 1) * paired if n > 1 else math.nan
        print(f"{force} ({n} pairs): base {statistics.mean(b):.3f} +- {b_se:.3f} N, other {statistics.mean(o):.3f} +- "
              f"{o_se:.3f} N; other - base {diff:+.3f} N (+- {math.hypot(b_se, o_se):.3f} by the cuts' own errors, "
              f"+- {paired:.3f} by the paired spread, 95 % [{diff - half:+.3f}, {diff + half:+.3f}] by Student's t), "
              f"{100 * diff / statistics.mean(b):+.0f} % "
              f"[{100 * (diff - half) / statistics.mean(b):+.0f} %, {100 * (diff + half) / statistics.mean(b):+.0f} %]")
    for name, study in (("base", base), ("other", other)):
        mean = lambda k: known_mean(study[p][k] for p in pairs)  # noqa: E731
        print(f"{name}: {mean('disks'):.0f} disks integrated, steady damage depth "
              f"{mean(R.subsurface_damage_depth_steady_um):.0f} um (window floor {mean('damage_floor_um'):.0f} um), "
              f"{mean(R.cracks_subsurface_steady):.0f} steady subsurface cracks, {mean('wall_time_s'):.0f} s per cut; "
              f"tool in contact in {100 * mean('contact_share'):.1f} % of the steady samples, main force "
              f"{mean('main_force_in_contact_N'):.2f} N while in contact, "
              f"99th percentile {mean('main_force_p99_N'):.2f} N "
              f"(means of the packings that record them)")


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "record":
        write_records(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 3:
        compare(read_set(sys.argv[1]), read_set(sys.argv[2]))
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
