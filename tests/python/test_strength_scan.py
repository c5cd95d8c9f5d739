"""analysis/strength_scan.py: a scan of one strength over steady-cut records, on synthetic ones with known answers."""
import argparse
import csv
import math

import pytest

from repo_scripts import load

from kerf.result_keys import CutResults as R

ss = load("analysis/strength_scan.py")

COLUMNS = ["domain", "surface", "depth_of_cut_mm", "seed", R.main_force_N, R.thrust_force_N, R.width_mm,
           R.cracks_subsurface_steady, R.subsurface_damage_depth_steady_um]


def write_record(path, regular_main, groove_factor, width_mm=1.0):
    """Regular main forces regular_main[s] per packing (thrust half of it), rectangular groove_factor times them."""
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        for surface, factor in (("regular", 1.0), ("rectangular", groove_factor)):
            for seed, m in enumerate(regular_main, start=1):
                main = m * factor * width_mm
                w.writerow(["default", surface, 0.1, seed, main, 0.5 * main, width_mm, 1000 * seed, 300])
    return path


def rows_by(rows, quantity, surface):
    return {s: (n, v, lo, hi) for s, q, sf, n, v, lo, hi in rows if q == quantity and sf == surface}


def test_the_groove_effect_and_the_level_of_each_point_are_the_records(tmp_path):
    a = write_record(tmp_path / "a.csv", [0.10, 0.12, 0.11], 0.4, width_mm=2.0)
    off = write_record(tmp_path / "off.csv", [0.30, 0.36, 0.33], 0.9)
    rows = ss.point_rows(85.0, ss.read_record(a), "default", 0.1)
    rows += ss.point_rows(None, ss.read_record(off), "default", 0.1)
    level = rows_by(rows, "main_force_N_per_mm", "regular")
    assert math.isclose(level[85.0][1], 0.11) and math.isclose(level[None][1], 0.33)  # per mm of width
    assert level[85.0][2] < 0.11 < level[85.0][3]
    effect = rows_by(rows, "groove_effect_main", "rectangular/regular")
    assert math.isclose(effect[85.0][1], 0.4) and math.isclose(effect[None][1], 0.9)
    assert effect[85.0][2] < 0.4 < effect[85.0][3] and effect[85.0][0] == 3
    assert math.isclose(rows_by(rows, "groove_effect_thrust", "rectangular/regular")[85.0][1], 0.4)


def test_the_experiments_groove_effect_is_seed_000s():
    exp = ss.experiments(0.1)
    main = [17.8, 15.0, 16.7]
    grooved = [2.0, 2.9, 2.6]
    assert math.isclose(exp[("main_force_N_per_mm", "regular")], sum(main) / 3 / 25.4)
    assert math.isclose(exp[("groove_effect_main", "rectangular/regular")], sum(grooved) / sum(main))


def test_the_command_writes_its_table_and_rejects_a_point_without_a_value(tmp_path, capsys):
    a = write_record(tmp_path / "a.csv", [0.10, 0.12], 0.4)
    off = write_record(tmp_path / "off.csv", [0.30, 0.36], 0.9)
    out = tmp_path / "scan.csv"
    ss.main(["--off", str(off), "--point", f"330={a}", "--csv", str(out)])
    with open(out, newline="") as f:
        rows = list(csv.DictReader(f))
    assert {r["strength_MPa"] for r in rows} == {"330.0", "off"}
    assert "groove_effect_main" in capsys.readouterr().out
    with pytest.raises(argparse.ArgumentTypeError):
        ss.parse_point(f"strong={a}")
    with pytest.raises(argparse.ArgumentTypeError):
        ss.parse_point("-5=x.csv")
