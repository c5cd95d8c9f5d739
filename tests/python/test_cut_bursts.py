"""analysis/cut_bursts.py: the concentration of a cut's work, on synthetic force records with a known answer."""
import json

import numpy as np
import pytest

from repo_scripts import load

from kerf.result_keys import CutResults as R

cb = load("analysis/cut_bursts.py")


def write_cut(folder, force, travel_mm, seed=1, steady_from_mm=0.0):
    """A cut at 0.1 mm depth of cut (bins of 0.01 mm) with the main force `force` sampled at `travel_mm`."""
    folder.mkdir(parents=True)
    summary = {"material": {"name": "glass"}, "specimen": {"seed": seed},
               "cut": {"cut": {"depth_of_cut_mm": 0.1}, "grooves": {"shape": "none"},
                       "active_window": {"enabled": True, "ahead_depths": 7, "behind_depths": 3, "below_depths": 4}},
               "results": {R.main_force_N: float(np.mean(force)), R.steady_from_travel_mm: steady_from_mm,
                           R.steady_to_travel_mm: float(travel_mm[-1])}}
    (folder / "summary.json").write_text(json.dumps(summary))
    rows = ["tool_travel_mm,time_s,main_force_N,thrust_force_N"]
    rows += [f"{x!r},0,{f!r},0" for x, f in zip(travel_mm, force)]
    (folder / "forces.csv").write_text("\n".join(rows) + "\n")


def test_a_steady_force_spreads_its_work_and_a_spiky_one_concentrates_it(tmp_path):
    travel = np.arange(0, 100000) * 1e-4  # 10 mm in 0.1 um samples: 1000 bins of 0.01 mm
    write_cut(tmp_path / R.steady, np.full(travel.size, 0.5), travel)
    _, _, m = cb.cut_bursts(tmp_path / R.steady)
    assert m["work_share_top_1pc"] == pytest.approx(0.01, rel=0.02)  # 10 bins of 1000
    assert m["travel_share_half_work"] == pytest.approx(0.5, abs=0.002)
    # A background of 0.1 N (1 N mm over the 10 mm) plus 10 spikes of 0.9 N mm each, each within one bin: the top 1 %
    # of the bins (10 of 1000) hold the spikes and their background, (10 x 0.9 + 10 x 0.001) / 10.
    spiky = np.full(travel.size, 0.1)
    for k in range(10):
        start = 5000 + 9000 * k
        spiky[start:start + 50] += 0.9 / (50 * 1e-4)
    write_cut(tmp_path / "spiky", spiky, travel, seed=2)
    _, _, s = cb.cut_bursts(tmp_path / "spiky")
    assert s["work_share_top_1pc"] == pytest.approx((10 * 0.9 + 10 * 0.001) / 10, rel=1e-9)
    assert s["travel_share_half_work"] == pytest.approx(6 / 1000, abs=1e-9)  # 5 spikes hold 45 %, the 6th passes 50
    assert s["peak_main_force_N"] == pytest.approx(spiky.max())


def test_the_steady_part_only_and_one_condition_over_packings(tmp_path):
    travel = np.arange(0, 20000) * 1e-4
    force = np.full(travel.size, 0.2)
    force[:5000] = 50.0  # the entry, before the steady part begins at 0.5 mm: left out
    for seed in (1, 2):
        write_cut(tmp_path / "study" / "items" / f"c_{seed}", force, travel, seed=seed, steady_from_mm=0.5)
    cuts = [cb.cut_bursts(f) for f in cb.folders([tmp_path / "study"], needs="forces.csv")]
    assert len(cuts) == 2
    assert cuts[0][2]["peak_main_force_N"] == pytest.approx(0.2)
    (key, row), = cb.table(cuts).items()
    assert key[2] == "regular" and row["travel_share_half_work"].n == 2
    assert row["travel_share_half_work"].value == pytest.approx(0.5, abs=0.01)


def test_a_cut_read_only_up_to_a_travel_keeps_that_part_alone(tmp_path):
    # 0.1 N for the first 5 mm, 0.3 N after: read to 5 mm the mean is 0.1 N and the work spread evenly; read whole, the
    # mean is 0.2 N and the later half holds three quarters of the work.
    travel = np.arange(0, 100000) * 1e-4
    force = np.where(travel < 5.0, 0.1, 0.3)
    write_cut(tmp_path / "a", force, travel)
    _, _, part = cb.cut_bursts(tmp_path / "a", to_travel_mm=5.0 - 1e-9)
    _, _, whole = cb.cut_bursts(tmp_path / "a")
    assert part[R.main_force_N] == pytest.approx(0.1)
    assert part["travel_share_half_work"] == pytest.approx(0.5, abs=0.005)
    assert whole[R.main_force_N] == pytest.approx(0.2, rel=1e-3)
    assert whole["travel_share_half_work"] == pytest.approx(1 / 3, abs=0.002)


def test_the_cumulative_work_is_a_staircase_of_the_jams_and_the_figure_is_drawn(tmp_path):
    travel = np.arange(0, 20000) * 1e-4  # 2 mm
    force = np.full(travel.size, 0.1)
    force[10000:10010] += 100.0  # one jam of 100 N over 1 um: 0.1 mJ per mm of width
    write_cut(tmp_path / "study" / "items" / "c_1", force, travel, steady_from_mm=0.5)
    x, work = cb.cumulative_work(tmp_path / "study" / "items" / "c_1")
    assert x[0] == 0 and x[-1] == pytest.approx(1.5, abs=1e-3)
    assert work[-1] == pytest.approx(0.1 * 1.5 + 0.1, rel=1e-3)
    jump = work[5010] - work[4999]  # across the jam at 1.0 mm of travel, 0.5 mm into the steady part
    assert jump == pytest.approx(0.1 + 11 * 0.1e-4, rel=1e-6)
    png = tmp_path / "w.png"
    assert cb.main([str(tmp_path / "study"), "--figure", str(png)]) == 0
    assert png.read_bytes()[:4] == b"\x89PNG"
