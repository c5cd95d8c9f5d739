"""analysis/cut_events.py: a cut's load events and the cracks they drive below the cut line, on synthetic outputs with a
known answer."""
import csv
import json
import math

import numpy as np
import pytest

from repo_scripts import load

from kerf.result_keys import CracksColumns as C
from kerf.result_keys import CutResults as R
from kerf.result_keys import keys

ce = load("analysis/cut_events.py")

SPEED_MM_PER_S = 2000.0  # 2 m/s: time = travel / speed
STEP_MM = 1e-4  # 0.1 um of travel per sample


def write_cut(folder, force_n_per_mm, cracks, y_cut_mm=0.9, steady=(0.5, 3.0), zone=False, fine=None):
    """A cut's folder: the cutting force per sample (1 mm wide, thrust half of it), cracks as (travel_mm, depth_um)."""
    folder.mkdir(parents=True)
    travel = np.arange(force_n_per_mm.size) * STEP_MM
    specimen = {"seed": 1, "height_mm": 1.0}
    if fine is not None:  # a run of kerf 0.2 and later names the fine region's radii, 0 when it has none
        specimen.update(fine_radius_min_um=3.0 if fine else 0.0, fine_radius_max_um=3.9 if fine else 0.0)
    cut = {"cut": {"depth_of_cut_mm": 0.1}, "grooves": {"shape": "none"}, "tool": {"rake_deg": -15.0},
           "active_window": {"enabled": True, "ahead_depths": 7, "behind_depths": 3, "below_depths": 4}}
    if zone:
        cut["edge_zone"] = {"enabled": True}
    summary = {"material": {"name": "glass"}, "specimen": specimen, "cut": cut,
               "results": {R.width_mm: 1.0, R.cut_line_y_mm: y_cut_mm, R.steady_from_travel_mm: steady[0],
                           R.steady_to_travel_mm: steady[1]}}
    (folder / "summary.json").write_text(json.dumps(summary))
    rows = ["tool_travel_mm,time_s,cutting_force_N,thrust_force_N"]
    rows += [f"{x!r},{x / SPEED_MM_PER_S!r},{f!r},{0.5 * f!r}" for x, f in zip(travel, force_n_per_mm)]
    (folder / "forces.csv").write_text("\n".join(rows) + "\n")
    rows = [",".join(keys(C))]
    rows += [f"{x / SPEED_MM_PER_S!r},5.0,{y_cut_mm - 1e-3 * d!r},0,10,tension,1,0,subsurface" for x, d in cracks]
    (folder / "cracks.csv").write_text("\n".join(rows) + "\n")
    return travel


def pulse(force, travel, start_mm, length_mm, peak):
    """A triangular load of `peak` N/mm over [start, start + length) of travel."""
    on = (travel >= start_mm) & (travel < start_mm + length_mm)
    force[on] = peak * (1.0 - np.abs((travel[on] - start_mm) / length_mm * 2.0 - 1.0)) + 0.1
    return on


def test_events_their_peaks_and_the_cracks_they_drive(tmp_path):
    travel = np.arange(30001) * STEP_MM  # 3 mm
    force = np.zeros(travel.size)
    pulse(force, travel, 1.0, 0.01, 3.0)  # a shallow event
    pulse(force, travel, 2.0, 0.02, 12.0)  # a deep one
    pulse(force, travel, 2.5, 0.01, 0.5)  # loaded, but below the events' 1 N/mm: no event
    pulse(force, travel, 0.2, 0.01, 30.0)  # in the entry, before the steady part: left out
    cracks = [(1.005, 10.0), (2.005, 50.0), (2.015, 150.0), (2.01, -20.0),  # the events' cracks (one above the line)
              (2.505, 300.0), (1.5, 500.0), (0.205, 400.0)]  # the small load's, one between events, one in the entry
    write_cut(tmp_path / "cut", force, cracks)
    key, seed, m, events = ce.cut_events(tmp_path / "cut")
    assert seed == 1 and key[0] == "glass, rake -15 deg" and key[2] == "regular"
    assert [round(e["peak_cutting_N_per_mm"], 6) for e in events] == pytest.approx([3.1, 12.1], abs=1e-3)
    assert [e["deepest_crack_um"] for e in events] == pytest.approx([10.0, 150.0])
    assert [e["cracks"] for e in events] == [1, 3]
    assert events[1]["thrust_at_peak_N_per_mm"] == pytest.approx(0.5 * events[1]["peak_cutting_N_per_mm"])
    steady = (travel >= 0.5) & (travel <= 3.0)
    f = force[steady]
    small = (travel[steady] >= 2.5) & (travel[steady] < 2.51)
    assert sum(e["impulse_share"] for e in events) == pytest.approx(1.0 - f[small].sum() / f.sum())
    assert m["loaded_share"] == pytest.approx(np.mean(f > 0.05))
    assert m["events_per_mm"] == pytest.approx(2 / 2.5, rel=1e-3)
    assert m["deep_event_share"] == 0.5
    assert m["deep_event_peak_N_per_mm"] == pytest.approx(12.1, abs=1e-3)
    assert m["shallow_event_peak_N_per_mm"] == pytest.approx(3.1, abs=1e-3)


def test_loads_closer_than_the_merge_gap_are_one_event(tmp_path):
    travel = np.arange(20001) * STEP_MM
    force = np.zeros(travel.size)
    pulse(force, travel, 1.0, 0.005, 4.0)
    pulse(force, travel, 1.0060, 0.005, 6.0)  # 1 um after the first ends: joined at the default 2 um
    write_cut(tmp_path / "cut", force, [(1.009, 30.0)], steady=(0.5, 2.0))
    _, _, _, joined = ce.cut_events(tmp_path / "cut")
    _, _, _, apart = ce.cut_events(tmp_path / "cut", merge_um=0.5)
    assert len(joined) == 1 and joined[0]["peak_cutting_N_per_mm"] == pytest.approx(6.1, abs=1e-2)
    assert joined[0]["deepest_crack_um"] == pytest.approx(30.0)
    assert len(apart) == 2 and apart[0]["deepest_crack_um"] == 0.0  # the crack is born in the second


def test_the_line_load_crack_depth_closes_on_the_toughness():
    # K = P sqrt(2 / (pi a)) at the depth returned gives K_IC back, and the depth goes as P^2.
    for p_n_per_mm, k in ((3.4, 0.75), (12.5, 0.75), (20.0, 0.5)):
        a_m = ce.lefm_depth_um(p_n_per_mm, k) * 1e-6
        assert p_n_per_mm * 1e3 * math.sqrt(2 / (math.pi * a_m)) / 1e6 == pytest.approx(k, rel=1e-12)
    assert ce.lefm_depth_um(2.0, 0.75) / ce.lefm_depth_um(1.0, 0.75) == pytest.approx(4.0)


def test_the_condition_names_the_edge_zone_and_a_fine_region(tmp_path):
    travel = np.arange(10001) * STEP_MM
    force = np.zeros(travel.size)
    pulse(force, travel, 0.7, 0.01, 5.0)
    write_cut(tmp_path / "zone", force, [], steady=(0.5, 1.0), zone=True, fine=True)
    key, _, m, events = ce.cut_events(tmp_path / "zone")
    assert key[0] == "glass, rake -15 deg, edge zone, disks 3-3.9 um at the cut line"
    assert len(events) == 1 and events[0]["cracks"] == 0 and math.isnan(m["deep_event_peak_N_per_mm"])
    write_cut(tmp_path / "none", force, [], steady=(0.5, 1.0), fine=False)
    assert ce.cut_events(tmp_path / "none")[0][0] == "glass, rake -15 deg"


def test_main_writes_the_tables_and_the_figure(tmp_path):
    travel = np.arange(10001) * STEP_MM
    force = np.zeros(travel.size)
    pulse(force, travel, 0.7, 0.01, 5.0)
    write_cut(tmp_path / "a", force, [(0.705, 40.0)], steady=(0.5, 1.0))
    ce.main([str(tmp_path / "a"), "--events-csv", str(tmp_path / "e.csv"), "--cuts-csv", str(tmp_path / "c.csv"),
             "--figure", str(tmp_path / "f.png")])
    events = list(csv.DictReader(open(tmp_path / "e.csv")))
    assert len(events) == 1 and float(events[0]["deepest_crack_um"]) == pytest.approx(40.0)
    assert len(list(csv.DictReader(open(tmp_path / "c.csv")))) == 1
    assert (tmp_path / "f.png").stat().st_size > 0
