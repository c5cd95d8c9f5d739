"""analysis/edge_zone_pilot.py: a record with and without the edge zone, on synthetic rows with known answers."""
import csv

from repo_scripts import load

from kerf.result_keys import CutResults as R

ez = load("analysis/edge_zone_pilot.py")


def write(path, forces):
    """forces: {(surface, zone): [cutting per packing]}; the thrust is half the cutting force."""
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["surface", "edge_zone", "seed", R.cutting_force_N_per_mm,
                                          R.thrust_force_N_per_mm, R.edge_zone_intact_share_steady,
                                          R.tied_share_behind_depth_0_25_um_steady, R.subsurface_damage_depth_steady_um])
        w.writeheader()
        for (surface, zone), values in forces.items():
            for seed, c in enumerate(values, start=1):
                w.writerow({"surface": surface, "edge_zone": zone, "seed": seed, R.cutting_force_N_per_mm: c,
                            R.thrust_force_N_per_mm: c / 2, R.edge_zone_intact_share_steady: 0.5 if zone == "on" else "",
                            R.tied_share_behind_depth_0_25_um_steady: 0.8, R.subsurface_damage_depth_steady_um: 200})


def test_a_grooved_force_at_a_fixed_fraction_gives_that_groove_effect_exactly(tmp_path):
    regular = [0.40, 0.50, 0.45, 0.55]
    write(tmp_path / "r.csv", {("regular", "on"): regular, ("rectangular", "on"): [0.25 * x for x in regular],
                               ("regular", "off"): regular, ("rectangular", "off"): [0.5 * x for x in regular]})
    text = ez.report(ez.read(tmp_path / "r.csv"))
    on = [l for l in text.splitlines() if l.startswith("groove effect") and "cutting" in l and "zone on" in l][0]
    off = [l for l in text.splitlines() if l.startswith("groove effect") and "cutting" in l and "zone off" in l][0]
    # independent means, so the interval is not degenerate, but it holds the exact ratio of the means
    lo, hi = (float(x) for x in on.split("[")[1].rstrip("]").split(", "))
    assert float(on.split(": ")[1].split()[0]) == 0.25 and lo < 0.25 < hi
    assert float(off.split(": ")[1].split()[0]) == 0.5
    assert "zone effect (on / off), cutting_force_N_per_mm, regular: 1 [" in text


def test_the_table_has_a_row_per_surface_and_zone_with_its_packings(tmp_path):
    write(tmp_path / "r.csv", {("regular", "on"): [0.4, 0.5], ("regular", "off"): [0.6]})
    rows = [l for l in ez.report(ez.read(tmp_path / "r.csv")).splitlines() if l.startswith("| regular")]
    assert len(rows) == 2
    on = [r for r in rows if "| on |" in r][0]
    off = [r for r in rows if "| off |" in r][0]
    assert "| 2 |" in on and "0.45 [" in on and "0.5 [0.5, 0.5]" in on  # the zone's share: the same in both
    assert "| 1 |" in off and "0.6 (n = 1)" in off and "| - |" in off  # one packing: no interval; no zone: no share


def test_a_ratio_whose_denominator_is_not_resolved_from_zero_says_so(tmp_path):
    write(tmp_path / "r.csv", {("regular", "on"): [0.01, -0.01, 0.02, -0.015], ("rectangular", "on"): [0.2, 0.3, 0.25, 0.2]})
    line = [l for l in ez.report(ez.read(tmp_path / "r.csv")).splitlines() if "groove effect" in l and "cutting" in l][0]
    assert "unbounded" in line


def test_a_force_with_a_known_depth_independent_part_is_split_into_it(tmp_path):
    # F = 0.3 + 2 h (N/mm, h in mm) on every packing, with a packing spread added equally at both depths' means
    spread = [-0.02, 0.01, 0.0, 0.01]
    write(tmp_path / "a.csv", {("regular", "on"): [0.3 + 2 * 0.1 + d for d in spread]})
    write(tmp_path / "b.csv", {("regular", "on"): [0.3 + 2 * 0.2 + d for d in spread]})
    line = ez.split(ez.read(tmp_path / "a.csv"), ez.read(tmp_path / "b.csv"), 0.1).splitlines()[0]
    assert "F0 0.3 [" in line and "k 2 [" in line and "depth effect 1.4 [" in line


def test_a_change_that_adds_a_known_amount_to_every_packing_is_found_paired_exactly(tmp_path):
    # The baseline's packings spread widely; the changed record adds 0.1 N/mm to each: a paired difference of 0.1
    # with a zero-width interval (an unpaired one would be wide); a packing in one record only is left out.
    base = [0.2, 0.9, 0.5, 1.3]
    write(tmp_path / "base.csv", {("regular", "on"): base})
    write(tmp_path / "new.csv", {("regular", "on"): [x + 0.1 for x in base] + [5.0]})
    rows = ez.paired(ez.read(tmp_path / "new.csv"), ez.read(tmp_path / "base.csv")).splitlines()
    row = [r for r in rows if r.startswith("| regular | on |")][0]
    cells = [c.strip() for c in row.split("|")[1:-1]]
    assert cells[2] == "4"  # the fifth packing has no partner
    value, interval = cells[3].split(" [")
    assert abs(float(value) - 0.1) < 1e-12
    lo, hi = (float(x) for x in interval.rstrip("]").split(", "))
    assert abs(lo - 0.1) < 1e-9 and abs(hi - 0.1) < 1e-9


def test_another_specimen_beside_the_pilot_gives_the_unpaired_difference_of_the_means(tmp_path):
    # Independent packings: the difference of the means, with a Welch interval that holds it and is not degenerate;
    # each of the other record's groups against each of the base's groups on the same surface, none across surfaces.
    write(tmp_path / "base.csv", {("regular", "on"): [0.4, 0.5, 0.45, 0.55], ("regular", "off"): [0.6, 0.7, 0.65],
                                  ("rectangular", "on"): [0.2, 0.3]})
    write(tmp_path / "fine.csv", {("regular", "off"): [0.3, 0.32, 0.31, 0.37]})
    rows = ez.beside(ez.read(tmp_path / "fine.csv"), ez.read(tmp_path / "base.csv")).splitlines()[2:]
    assert len(rows) == 2
    on = [r for r in rows if r.startswith("| regular | off | on |")][0]
    cells = [c.strip() for c in on.split("|")[1:-1]]
    assert cells[3] == "4, 4"
    value, interval = cells[4].split(" [")
    assert abs(float(value) - (0.325 - 0.475)) < 1e-9
    lo, hi = (float(x) for x in interval.rstrip("]").split(", "))
    assert lo < float(value) < hi and hi - lo > 0.05


def write_tagged(path, forces, tag):
    """forces: {(surface, zone, tag value or ""): [cutting per packing]}; the thrust is half the cutting force."""
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["surface", "edge_zone", tag, "seed", R.cutting_force_N_per_mm,
                                          R.thrust_force_N_per_mm])
        w.writeheader()
        for (surface, zone, value), values in forces.items():
            for seed, c in enumerate(values, start=1):
                w.writerow({"surface": surface, "edge_zone": zone, tag: value, "seed": seed,
                            R.cutting_force_N_per_mm: c, R.thrust_force_N_per_mm: c / 2})


def test_a_tag_splits_a_surface_and_each_of_its_groups_meets_the_regular_rows_of_another_record(tmp_path):
    # The damaged grooves' record has no regular cuts; the regular ones come from a record of the same packings
    # (--with). Each damage depth is a group of its own with its own groove effect, exactly its fraction.
    regular = [0.40, 0.50, 0.45, 0.55]
    write_tagged(tmp_path / "damaged.csv", {("rectangular", "on", "25"): [0.5 * x for x in regular],
                                            ("rectangular", "on", "50"): [0.2 * x for x in regular]}, "damage_um")
    write(tmp_path / "base.csv", {("regular", "on"): regular, ("rectangular", "on"): [0.3 * x for x in regular]})
    groups = ez.read(tmp_path / "damaged.csv", ["damage_um"])
    assert sorted(groups) == [("rectangular, damage_um=25", "on"), ("rectangular, damage_um=50", "on")]
    ez.read(tmp_path / "base.csv", ["damage_um"], groups)  # its rows have no such tag: their plain surface
    text = ez.report(groups)
    effects = {l.split("(")[1].split(" /")[0]: float(l.split(": ")[1].split()[0])
               for l in text.splitlines() if l.startswith("groove effect") and "cutting" in l}
    assert effects == {"rectangular": 0.3, "rectangular, damage_um=25": 0.5, "rectangular, damage_um=50": 0.2}


def test_a_tagged_group_is_paired_with_its_plain_surface_in_the_baseline(tmp_path):
    base = [0.2, 0.9, 0.5, 1.3]
    write(tmp_path / "base.csv", {("rectangular", "on"): base})
    write_tagged(tmp_path / "damaged.csv", {("rectangular", "on", "50"): [x - 0.05 for x in base]}, "damage_um")
    rows = ez.paired(ez.read(tmp_path / "damaged.csv", ["damage_um"]),
                     ez.read(tmp_path / "base.csv", ["damage_um"])).splitlines()[2:]
    assert len(rows) == 1 and rows[0].startswith("| rectangular, damage_um=50 | on | 4 |")
    assert abs(float(rows[0].split("|")[4].split(" [")[0]) + 0.05) < 1e-12


def test_a_tag_on_both_surfaces_divides_each_grooved_group_by_the_regular_group_of_its_own_value(tmp_path):
    # The lateral crack's length acts on both surfaces: each length's groove effect is its own grooved cuts over its own
    # regular ones (exactly its fraction), not over the plain regular surface's.
    regular = [0.40, 0.50, 0.45, 0.55]
    write_tagged(tmp_path / "crack.csv", {("regular", "on", "30"): regular,
                                          ("rectangular", "on", "30"): [0.4 * x for x in regular],
                                          ("regular", "on", "300"): [2 * x for x in regular],
                                          ("rectangular", "on", "300"): [0.2 * x for x in regular]}, "crack")
    write(tmp_path / "base.csv", {("regular", "on"): [10 * x for x in regular]})
    groups = ez.read(tmp_path / "crack.csv", ["crack"])
    ez.read(tmp_path / "base.csv", ["crack"], groups)
    text = ez.report(groups)
    effects = {l.split("(")[1].split(")")[0]: float(l.split(": ")[1].split()[0])
               for l in text.splitlines() if l.startswith("groove effect") and "cutting" in l}
    assert effects == {"rectangular, crack=30 / regular, crack=30": 0.4,
                       "rectangular, crack=300 / regular, crack=300": 0.1}
