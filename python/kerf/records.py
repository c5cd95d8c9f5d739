"""kerf.records: the readers of kerf's study records and cut outputs, in one place (issue 56).

* Study records (`kerf-dem study` appends one row per finished cut to data/studies/results/*.csv): read_record,
  read_records, per_width; the experiments' and the paper's DEM's table (read_experiments) and a reference's mean
  (reference).
* Steady-cut sets compared packing by packing (a study directory or a record file written from one; RECORD_FIELDS):
  read_set, item_dirs, record_of.
* A cut's output folder (summary.json, forces.csv, cracks.csv): folders, condition_of, contact_statistics,
  intermittency.

    from kerf.records import read_record, per_width
    cuts = read_record("data/studies/results/seed000_steady.csv")   # {(domain, surface, depth_mm): {seed: row}}
    by = read_record("data/studies/results/issue54_edge_zone_steady.csv", by_variant=True)  # {"zone on": cuts, ...}
"""
import csv
import json
import math
import pathlib
import statistics

import numpy as np

from kerf.result_keys import ActiveWindowResults as W
from kerf.result_keys import CutResults as R
from kerf.result_keys import ForcesCsvColumns as F
from kerf.stats import mean_of

GROOVED = ("rectangular", "trapezoidal")


def both_names(values):
    """`values` (a dict: a record's row, a summary's results) with the cutting force under both its names (issue 55
    item 5): kerf-dem 0.1.0 wrote `main_force_*`; 0.2.0 writes `cutting_force_*` (kerf-forces' name) and, until 0.3.0,
    `main_force_*` beside it. Whichever a record holds, a row read here has both."""
    for key in list(values):
        for old, new in (("main_force", "cutting_force"), ("cutting_force", "main_force")):
            if key.startswith(old):
                values.setdefault(new + key[len(old):], values[key])
    return values


def cutting_force(values, unit="N"):
    """The cutting force `cutting_force_<unit>` of `values` (a summary's results, a record's or an items.csv row, a
    travel window), or `main_force_<unit>` in one written before 0.2.0 (unit "N", "sem_N", "N_per_mm", ...)."""
    key = f"cutting_force_{unit}"
    return values[key] if key in values else values[f"main_force_{unit}"]


def cutting_force_column(names):
    """The cutting force's column among a forces.csv's `names`: cutting_force_N, or main_force_N in a cut written
    before 0.2.0."""
    return F.cutting_force_N if F.cutting_force_N in names else F.main_force_N


# A record's columns that choose the model (a study's tags that its conditions differ in beside the condition's own:
# domain, surface, depth), each with the name the reports give it. A cut's *variant* is its values of those its record
# has, in this order ("zone on, layer_factor 2.46"; "" where it has none). A new model choice is one more entry here.
MODEL_CHOICES = (("edge_zone", "zone"), ("layer_factor", "layer_factor"),
                 ("groove_damage_depth_um", "groove layer um"), ("groove_damage_model", "layer as"))
# Model choices that act on the grooved surfaces only (the grooves' laser-affected layer, grooves.damage_depth_um, and
# how the cut represents it, grooves.damage_model): a variant with one has no regular cuts of its own, its regular cuts
# are those of the variant without it (regular_variant_of).
GROOVES_ONLY_CHOICES = ("groove_damage_depth_um", "groove_damage_model")


def variant_of(row):
    """The model variant of a record's row (or a study condition's tags): 'zone off', 'zone on, layer_factor 2.46', ''
    for a row with no model-choice column (MODEL_CHOICES) or only empty ones; numbers as %g."""
    parts = []
    for column, name in MODEL_CHOICES:
        value = row.get(column, "")
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            if math.isfinite(value):
                parts.append(f"{name} {value:g}")
        elif value not in ("", None):
            parts.append(f"{name} {str(value).lower() if isinstance(value, bool) else value}")
    return ", ".join(parts)


def regular_variant_of(variant):
    """The variant whose regular cuts `variant` shares: `variant` less its grooves-only choices (GROOVES_ONLY_CHOICES;
    'zone on, groove layer um 25' -> 'zone on'); `variant` itself when it has none."""
    names = tuple(f"{name} " for column, name in MODEL_CHOICES if column in GROOVES_ONLY_CHOICES)
    return ", ".join(part for part in variant.split(", ") if part and not part.startswith(names))


def read_record(path, cuts=None, by_variant=False):
    """{(domain, surface, depth_mm): {seed: row}} with numbers as floats, added to `cuts` where given (records merge:
    one model choice's cuts spread over two studies). Two cuts of one (domain, surface, depth) on one packing, in this
    record or against `cuts` (conditions that differ in another tag, e.g. the disk size), are an error (ValueError
    naming them): kept, one would silently replace the other. by_variant: {variant: {(domain, surface, depth_mm):
    {seed: row}}} instead, the cuts split by their model variant (variant_of: the record's model-choice columns; ''
    for a record without any), so that only two cuts of one variant, condition and packing are an error."""
    cuts = {} if cuts is None else cuts
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            key = (row["domain"], row["surface"], round(float(row["depth_of_cut_mm"]), 6))
            values = {}
            for k, v in row.items():
                try:
                    values[k] = float(v)
                except (TypeError, ValueError):
                    values[k] = v
            both_names(values)
            seed = int(float(row["seed"]))
            variant = variant_of(values) if by_variant else ""
            mine = (cuts.setdefault(variant, {}) if by_variant else cuts).setdefault(key, {})
            if seed in mine:
                named = f" ({variant})" if variant else ""
                raise ValueError(f"{path}: a second cut of {key[0]}/{key[1]}/{key[2]:g} mm{named} on packing {seed} "
                                 "(conditions that differ in another tag, or a cut in two records: compare them apart)")
            mine[seed] = values
    return cuts


def read_records(paths, by_variant=False):
    """read_record of several records merged (by_variant: split by the model variant, as read_record's)."""
    cuts = {}
    for path in paths:
        read_record(path, cuts, by_variant)
    return cuts


def per_width(row, force):
    """A record row's `force` ('cutting' or its old name 'main', 'thrust') per mm of its width (width_mm; 1 mm where it
    has none). The cutting force is read as cutting_force_N, main_force_N in a row not read through both_names."""
    width = row.get(R.width_mm, 1.0)
    width = width if isinstance(width, float) and math.isfinite(width) and width > 0 else 1.0
    if force in ("cutting", "main"):
        return cutting_force(row) / width
    return row[{"thrust": R.thrust_force_N}[force]] / width


def read_experiments(path):
    """{(source, surface, depth_mm): {"main": [...], "thrust": [...]}} per mm of width (the experiments' and the
    paper's DEM's table, validation/soda_lime_cutting/soda_lime_orthogonal_cutting.csv's form; # lines are comments)."""
    out = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(line for line in f if not line.startswith("#")):
            key = (row["source"], row["surface"], round(float(row["depth_of_cut_mm"]), 6))
            width = float(row[R.width_mm])
            d = out.setdefault(key, {"main": [], "thrust": []})
            d["main"].append(float(row[cutting_force_column(row)]) / width)
            d["thrust"].append(float(row[R.thrust_force_N]) / width)
    return out


def reference(experiments, source, surface, depth, quantity):
    """The mean (kerf.stats.Estimate) of a reference's tests, `source` 'experiment' or 'paper_dem', for a surface
    (rectangular and trapezoidal are the references' one grooved surface), depth of cut (mm) and force ('main',
    'thrust'); None where the table has none."""
    surface = "grooved" if surface in GROOVED else surface
    values = experiments.get((source, surface, depth), {}).get(quantity)
    return mean_of(values) if values else None


# Steady-cut sets compared packing by packing (analysis/compare_steady_cuts.py): one row per cut; a cell left empty
# is not known (a record entered from the documentation).
RECORD_FIELDS = ["condition", "seed", "speed_m_per_s", "window", "disks", "damage_floor_um", R.main_force_N,
                 R.main_force_sem_N, R.thrust_force_N, R.thrust_force_sem_N, R.steady_from_travel_mm,
                 R.subsurface_damage_depth_steady_um, R.cracks_subsurface_steady, "wall_time_s", "contact_share",
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
        main = [float(r[cutting_force_column(r)]) for r in csv.DictReader(f)
                if float(r[F.tool_travel_mm]) >= steady_from_mm]
    touching = [x for x in main if x > 0]
    p99 = sorted(main)[min(len(main) - 1, int(0.99 * len(main)))]
    return len(touching) / len(main), statistics.mean(touching) if touching else 0.0, p99


def record_of(item_dir):
    """A finished study item's record (RECORD_FIELDS)."""
    s = json.loads((item_dir / "summary.json").read_text())
    r = both_names(s["results"])
    w = s.get("active_window")
    window = s["cut"].get("active_window", {"enabled": False})
    share, in_contact, p99 = contact_statistics(item_dir, r[R.steady_from_travel_mm])
    record = {"condition": s["study_item"]["condition"], "seed": s["study_item"]["seed"],
              "speed_m_per_s": s["cut"]["cut"]["speed_m_per_s"],
              "window": ", ".join(f"{window[k + '_depths']:g}" for k in ("ahead", "behind", "below", "above"))
              if window["enabled"] else "none",
              "disks": w[W.mean_window_particles] if w else s["n_particles"],
              "damage_floor_um": w[W.damage_depth_limit_um] if w else math.nan,
              "wall_time_s": s["study_item"]["wall_time_s"], "contact_share": share,
              "main_force_in_contact_N": in_contact, "main_force_p99_N": p99,
              "source": f"kerf {s['provenance']['git_commit']}, {s['provenance']['date']}"}
    for k in RECORD_FIELDS:
        if k not in record:
            record[k] = r[k]
    return record


def read_set(spec):
    """The cuts of a set, keyed by (tool speed, packing seed): from a record file (*.csv) or a study directory."""
    path, condition, seeds = parse_spec(spec)
    if path.suffix == ".csv":
        with open(path, newline="") as f:
            rows = [{k: v if k in TEXT_FIELDS else float(v) if v != "" else math.nan for k, v in row.items()}
                    for row in csv.DictReader(f)]
        rows = [both_names(r) for r in rows]
        rows = [r for r in rows if (condition is None or r["condition"] == int(condition))
                and (seeds is None or seeds[0] <= r["seed"] <= seeds[1])]
    else:
        rows = [record_of(d) for d in item_dirs(spec)]
    return {(r["speed_m_per_s"], int(r["seed"])): r for r in rows}


def folders(paths, needs="cracks.csv"):
    """The cut output folders among `paths` (a cut's own, or a study's items/*/) that have summary.json and `needs`."""
    for p in map(pathlib.Path, paths):
        if (p / "summary.json").is_file() and (p / needs).is_file():
            yield p
        for item in sorted((p / "items").glob("*")):
            if (item / "summary.json").is_file() and (item / needs).is_file():
                yield item


def condition_of(summary):
    """A cut's condition from its summary: (glass, window, surface, depth of cut in mm)."""
    material, cut = summary["material"], summary["cut"]
    depth_mm = cut["cut"]["depth_of_cut_mm"]
    window = cut.get("active_window", {})
    # The domain by its size in mm (ahead, behind, below; the seed-000 study's large window is 1.4/0.7/1.0 mm at both
    # depths), or "whole" when every disk is active.
    domain = "/".join(f"{window[k] * depth_mm:.2g}" for k in ("ahead_depths", "behind_depths", "below_depths")) + \
        " mm" if window.get("enabled") else "whole"
    # The tool's friction when it has its own (tool.friction_coefficient), else the glass's; its edge radius;
    # crushing grains, loose and tied; the window's options.
    tool = cut.get("tool", {}).get("friction_coefficient", -1)
    edge = cut.get("tool", {}).get("edge_radius_um", 0)
    grains, tied = window.get("grain_strength_MPa", 0), window.get("tied_grain_strength_MPa", 0)
    # The workpiece's disk radii when the summary gives them (a finer workpiece is another condition).
    specimen = summary.get("specimen", {})
    radii = f", radii {specimen['radius_min_um']:g}-{specimen['radius_max_um']:g} um" \
        if "radius_min_um" in specimen else ""
    glass = material.get("name", "custom") + radii + (f", tool mu {tool:g}" if tool >= 0 else "") + \
        (f", edge radius {edge:g} um" if edge > 0 else "") + \
        (f", grains crush at {grains:g} MPa" if grains > 0 else "") + \
        (f", tied disks crush at {tied:g} MPa" if tied > 0 else "") + \
        (", loose fragments removed" if window.get("remove_loose_fragments") else "") + \
        (f", absorbing layer {window['absorbing_depths']:g} depths" if window.get("absorbing_depths", 0) > 0 else "")
    # The surface, with its laser-affected layer if it has one (grooves.damage_depth_um, damage_broken_fraction).
    grooves = cut["grooves"]
    surface = {"none": "regular"}.get(grooves["shape"], grooves["shape"])
    if grooves.get("damage_depth_um", 0) > 0:
        surface += f" ({grooves['damage_depth_um']:g} um layer, {grooves.get('damage_broken_fraction', 1):g} broken)"
    return glass, domain, surface, depth_mm


def intermittency(item_dir, steady_from_mm):
    """How intermittent a cut is over its steady part (forces.csv from steady_from_mm of travel on): the share of the
    samples in which the tool touches (|main force| above 0.1 N), contact, and the share of the main force's sum
    carried by the largest 5 % of the samples, top5."""
    forces = np.genfromtxt(item_dir / "forces.csv", delimiter=",", names=True)
    main_force = forces[cutting_force_column(forces.dtype.names)][forces[F.tool_travel_mm] >= steady_from_mm]
    largest = np.sort(main_force)[::-1][: len(main_force) // 20]
    return {"contact": float(np.mean(np.abs(main_force) > 0.1)), "top5": float(largest.sum() / main_force.sum())}
