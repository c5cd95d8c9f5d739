"""kerf.records (python/kerf/records.py): the study records' reader and the references' means."""
import csv
import math
import statistics

import kerf.records as kr

from kerf.result_keys import CutResults as R
from kerf.result_keys import ForcesCsvColumns as F


def test_two_cuts_of_one_condition_on_one_packing_are_an_error_not_a_silent_choice(tmp_path):
    # A record of two disk sizes, both regular 0.1 mm in the default window on packing 1: read as one condition,
    # one cut would replace the other.
    with open(tmp_path / "record.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["domain", "surface", "depth_of_cut_mm", "seed", "radius_min_um", R.main_force_N])
        w.writerow(["default", "regular", 0.1, 1, 10, 0.27])
        w.writerow(["default", "regular", 0.1, 1, 5, 0.37])
    try:
        kr.read_record(tmp_path / "record.csv")
    except ValueError as e:
        assert "default/regular/0.1 mm on packing 1" in str(e)
    else:
        raise AssertionError("two cuts of one condition and packing were read silently")


def test_records_merge_and_forces_are_per_mm_of_width(tmp_path):
    # Two records of one study (a condition's packings in both): merged by condition and packing; a force per mm is
    # the force over the row's width, 1 mm where the row has none.
    for name, rows in (("a.csv", [[1, 0.8, 2.0], [2, 0.9, 2.0]]), ("b.csv", [[3, 0.3, ""]])):
        with open(tmp_path / name, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["domain", "surface", "depth_of_cut_mm", "seed", R.main_force_N, R.width_mm])
            for seed, force, width in rows:
                w.writerow(["large", "rectangular", 0.2, seed, force, width])
    cuts = kr.read_records([tmp_path / "a.csv", tmp_path / "b.csv"])
    rows = cuts[("large", "rectangular", 0.2)]
    assert sorted(rows) == [1, 2, 3]
    assert [kr.per_width(rows[s], "main") for s in (1, 2, 3)] == [0.4, 0.45, 0.3]


def test_a_reference_is_the_mean_of_its_tests_per_mm_and_grooved_for_both_groove_shapes(tmp_path):
    # Three tests on a 25.4 mm wide workpiece: the mean per mm is their mean over 25.4, its standard error the
    # sample standard deviation over sqrt(3); the references' one grooved surface answers for both shapes.
    path = tmp_path / "experiments.csv"
    path.write_text("# the experiments\nsource,surface,depth_of_cut_mm,width_mm,main_force_N,thrust_force_N\n" +
                    "".join(f"experiment,grooved,0.1,25.4,{f},1.0\n" for f in (2.0, 2.5, 3.0)))
    table = kr.read_experiments(path)
    for surface in ("rectangular", "trapezoidal"):
        e = kr.reference(table, "experiment", surface, 0.1, "main")
        assert math.isclose(e.value, 2.5 / 25.4, rel_tol=1e-12)
        assert math.isclose(e.se, statistics.stdev([2.0, 2.5, 3.0]) / 25.4 / math.sqrt(3), rel_tol=1e-12)
        assert e.dof == 2 and e.n == 3
    assert kr.reference(table, "experiment", "regular", 0.1, "main") is None


def test_the_cutting_force_is_read_under_either_name(tmp_path):
    # kerf-dem 0.1.0's records name it main_force_N; 0.2.0 writes cutting_force_N beside it, 0.3.0 only the latter
    # (issue 55 item 5): a record of either kind reads the same, under both names, per mm alike.
    for name, column in (("old.csv", R.main_force_N), ("new.csv", R.cutting_force_N)):
        with open(tmp_path / name, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["domain", "surface", "depth_of_cut_mm", "seed", column, column.replace("_N", "_sem_N"),
                        R.thrust_force_N, R.width_mm])
            w.writerow(["default", "regular", 0.1, 1, 0.8, 0.05, 0.4, 2.0])
    for name in ("old.csv", "new.csv"):
        row = kr.read_record(tmp_path / name)[("default", "regular", 0.1)][1]
        assert row[R.cutting_force_N] == row[R.main_force_N] == 0.8, (name, row)
        assert row[R.cutting_force_sem_N] == row[R.main_force_sem_N] == 0.05, (name, row)
        assert kr.per_width(row, "cutting") == kr.per_width(row, "main") == 0.4
    # A cut's forces.csv: the cutting force's column whichever the file has.
    assert kr.cutting_force_column([F.tool_travel_mm, R.main_force_N]) == R.main_force_N
    assert kr.cutting_force_column([F.tool_travel_mm, R.cutting_force_N, R.main_force_N]) == R.cutting_force_N
    # A row that has both keeps each (no overwrite): the new name's value stays the new name's.
    both = kr.both_names({R.cutting_force_N: 1.0, R.main_force_N: 2.0})
    assert both == {R.cutting_force_N: 1.0, R.main_force_N: 2.0}
    # A summary's results, an items.csv row, a travel window read as they are (analysis/): the new name first.
    assert kr.cutting_force({R.main_force_N: 2.0}) == 2.0
    assert kr.cutting_force({R.cutting_force_N: 1.0, R.main_force_N: 2.0}) == 1.0
    assert kr.cutting_force({R.main_force_sem_N: 0.1}, "sem_N") == 0.1
    assert kr.per_width({R.main_force_N: 0.8, R.width_mm: 2.0}, "cutting") == 0.4


def test_a_rows_variant_is_its_model_choice_columns_in_order(tmp_path):
    # The record's model-choice columns (MODEL_CHOICES: edge_zone, layer_factor) name a cut's variant, numbers as %g;
    # an empty cell is no choice, and a row with none is the one unnamed variant "".
    assert kr.variant_of({"edge_zone": "on", "layer_factor": 2.46, "seed": 1.0}) == "zone on, layer_factor 2.46"
    assert kr.variant_of({"layer_factor": 2.0, "edge_zone": "off"}) == "zone off, layer_factor 2"
    assert kr.variant_of({"edge_zone": "", "layer_factor": math.nan}) == ""
    assert kr.variant_of({"domain": "default"}) == ""
    with open(tmp_path / "record.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["domain", "surface", "depth_of_cut_mm", "edge_zone", "seed", R.main_force_N])
        w.writerows([["default", "regular", 0.1, zone, 1, force] for zone, force in (("off", 0.5), ("on", 0.6))])
    by = kr.read_record(tmp_path / "record.csv", by_variant=True)
    assert {v: c[("default", "regular", 0.1)][1][R.main_force_N] for v, c in by.items()} == {"zone off": 0.5,
                                                                                           "zone on": 0.6}
