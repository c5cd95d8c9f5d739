#!/usr/bin/env python3
"""Two sets of steady cuts compared packing by packing (e.g. data/studies/steady_window_undamped.json against the
same seeds of data/studies/steady_speed_undamped.json): the cuts of each set are matched by tool speed and packing
seed, and for the main and thrust forces the script prints both means with the cuts' own errors
(sqrt(sum sem^2) / n), the difference with that error and with the spread of the paired differences
(std / sqrt(n), and its Student-t 95 % interval), and the mean active-window disks (a cut without a window:
the workpiece's), steady damage depth (with the window's floor), steady subsurface cracks and wall time of each
set, and, from each cut's forces.csv over the steady part, the share of samples with the tool in contact (main
force > 0), the mean main force while in contact and the main force's 99th percentile.

    python3 bench/compare_steady_cuts.py BASE[:C][@A-B] OTHER[:C][@A-B]
    python3 bench/compare_steady_cuts.py record STUDY_DIR OUT.csv

A set is a study directory (its finished items) or a record file written by `record`: one row per cut with the
numbers above, so that a study's results outlive its item directories (data/studies/results/). :C takes only
condition C's cuts (a study with several conditions at one speed); @A-B only the packing seeds A to B.
"""
import csv
import json
import math
import os
import pathlib
import statistics
import sys

# One row per cut; a cell left empty is not known (a record entered from the documentation).
RECORD_FIELDS = ["condition", "seed", "speed_m_per_s", "window", "disks", "damage_floor_um", "main_force_N",
                 "main_force_sem_N", "thrust_force_N", "thrust_force_sem_N", "steady_from_travel_mm",
                 "subsurface_damage_depth_steady_um", "cracks_subsurface_steady", "wall_time_s", "contact_share",
                 "main_force_in_contact_N", "main_force_p99_N", "source"]
TEXT_FIELDS = {"window", "source"}


def parse_spec(spec):
    """PATH[:C][@A-B] -> (path, condition or None, (A, B) or None)."""
    spec, seeds = spec.rsplit("@", 1) if "@" in spec else (spec, None)
    path, condition = spec.rsplit(":", 1) if ":" in spec else (spec, None)
    return pathlib.Path(path), condition, tuple(int(v) for v in seeds.split("-", 1)) if seeds else None


def item_dirs(spec):
    """The finished items of STUDY_DIR, or of its condition C for STUDY_DIR:C, in name order; a suffix @A-B keeps
    only the packing seeds A to B (STUDY_DIR@1-4, STUDY_DIR:2@1-4)."""
    study_dir, condition, seeds = parse_spec(spec)
    found = sorted((study_dir / "items").glob(f"condition_{condition or '*'}_seed_*"))
    if seeds is None:
        return found
    return [d for d in found if seeds[0] <= int(d.name.rsplit("_", 1)[1]) <= seeds[1]]


def contact_statistics(item_dir, steady_from_mm):
    """Share of the steady samples with a main force > 0, mean main force over them, and its 99th percentile."""
    with open(item_dir / "forces.csv", newline="") as f:
        main = [float(r["main_force_N"]) for r in csv.DictReader(f) if float(r["tool_travel_mm"]) >= steady_from_mm]
    touching = [x for x in main if x > 0]
    p99 = sorted(main)[min(len(main) - 1, int(0.99 * len(main)))]
    return len(touching) / len(main), statistics.mean(touching) if touching else 0.0, p99


def record_of(item_dir):
    """A finished study item's record (RECORD_FIELDS)."""
    s = json.loads((item_dir / "summary.json").read_text())
    r = s["results"]
    w = s.get("active_window")
    window = s["cut"].get("active_window", {"enabled": False})
    share, in_contact, p99 = contact_statistics(item_dir, r["steady_from_travel_mm"])
    record = {"condition": s["study_item"]["condition"], "seed": s["study_item"]["seed"],
              "speed_m_per_s": s["cut"]["cut"]["speed_m_per_s"],
              "window": ", ".join(f"{window[k + '_depths']:g}" for k in ("ahead", "behind", "below", "above"))
              if window["enabled"] else "none",
              "disks": w["mean_window_particles"] if w else s["n_particles"],
              "damage_floor_um": w["damage_depth_limit_um"] if w else math.nan,
              "wall_time_s": s["study_item"]["wall_time_s"], "contact_share": share,
              "main_force_in_contact_N": in_contact, "main_force_p99_N": p99,
              "source": f"kerf {s['provenance']['git_commit']}, {s['provenance']['date']}"}
    for k in RECORD_FIELDS:
        if k not in record:
            record[k] = r[k]
    return record


def records(spec):
    """The cuts of a set, keyed by (tool speed, packing seed): from a record file (*.csv) or a study directory."""
    path, condition, seeds = parse_spec(spec)
    if path.suffix == ".csv":
        with open(path, newline="") as f:
            rows = [{k: v if k in TEXT_FIELDS else float(v) if v != "" else math.nan for k, v in row.items()}
                    for row in csv.DictReader(f)]
        rows = [r for r in rows if (condition is None or r["condition"] == int(condition))
                and (seeds is None or seeds[0] <= r["seed"] <= seeds[1])]
    else:
        rows = [record_of(d) for d in item_dirs(spec)]
    return {(r["speed_m_per_s"], int(r["seed"])): r for r in rows}


def own_error(study, pairs, force):
    """The standard error of the mean force over the packings `pairs` from the cuts' own errors: sqrt(sum sem^2) / n."""
    return math.sqrt(sum(study[p][f"{force}_force_sem_N"] ** 2 for p in pairs)) / len(pairs)


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


# Student's t, two-sided 95 %, by degrees of freedom (1-30); beyond, the Cornish-Fisher expansion about the
# normal's 1.959964 (Abramowitz & Stegun 26.7.5; within 1e-4 of the quantile from 30 degrees of freedom on).
T975 = [12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.160, 2.145, 2.131,
        2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042]


def t975(dof):
    if dof <= len(T975):
        return T975[dof - 1]
    z, n = 1.959964, float(dof)
    return (z + (z ** 3 + z) / (4 * n) + (5 * z ** 5 + 16 * z ** 3 + 3 * z) / (96 * n ** 2)
            + (3 * z ** 7 + 19 * z ** 5 + 17 * z ** 3 - 15 * z) / (384 * n ** 3))


def known_mean(values):
    """The mean of the known (finite) values; nan if none is known."""
    known = [v for v in values if math.isfinite(v)]
    return statistics.mean(known) if known else math.nan


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
        half = t975(n - 1) * paired if n > 1 else math.nan
        print(f"{force} ({n} pairs): base {statistics.mean(b):.3f} +- {b_se:.3f} N, other {statistics.mean(o):.3f} +- "
              f"{o_se:.3f} N; other - base {diff:+.3f} N (+- {math.hypot(b_se, o_se):.3f} by the cuts' own errors, "
              f"+- {paired:.3f} by the paired spread, 95 % [{diff - half:+.3f}, {diff + half:+.3f}] by Student's t), "
              f"{100 * diff / statistics.mean(b):+.0f} % "
              f"[{100 * (diff - half) / statistics.mean(b):+.0f} %, {100 * (diff + half) / statistics.mean(b):+.0f} %]")
    for name, study in (("base", base), ("other", other)):
        mean = lambda k: known_mean(study[p][k] for p in pairs)  # noqa: E731
        print(f"{name}: {mean('disks'):.0f} disks integrated, steady damage depth "
              f"{mean('subsurface_damage_depth_steady_um'):.0f} um (window floor {mean('damage_floor_um'):.0f} um), "
              f"{mean('cracks_subsurface_steady'):.0f} steady subsurface cracks, {mean('wall_time_s'):.0f} s per cut; "
              f"tool in contact in {100 * mean('contact_share'):.1f} % of the steady samples, main force "
              f"{mean('main_force_in_contact_N'):.2f} N while in contact, "
              f"99th percentile {mean('main_force_p99_N'):.2f} N "
              f"(means of the packings that record them)")


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "record":
        write_records(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 3:
        compare(records(sys.argv[1]), records(sys.argv[2]))
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
