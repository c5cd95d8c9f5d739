"""bench/cut_jam_frames.py: its reader of kerf's VTK frames and its figure, on a small cut's own frames."""
import json
import pathlib
import sys

import numpy as np

import kerf

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "bench"))
import cut_jam_frames as cj  # noqa: E402

SMALL_CUT = {"kind": "cut", "material": {"base": "soda_lime_glass_fj"},
             "specimen": {"width_mm": 0.4, "height_mm": 0.25, "radius_min_um": 10, "radius_max_um": 13, "seed": 1,
                          "growth_steps": 2000, "relax_steps": 500},
             "cut": {"depth_of_cut_mm": 0.05, "speed_m_per_s": 2, "length_mm": 0.03},
             "output": {"frame_every_samples": 20}}


def test_the_frames_read_back_and_the_figure_is_drawn(tmp_path):
    out = tmp_path / "cut"
    assert kerf.dem.run(SMALL_CUT, out=out, threads=1)["exit_status"] == 0
    summary = json.loads((out / "summary.json").read_text())
    frame = cj.read_vtp(out / "frame_0001.vtp")
    n = summary["n_particles"]  # no window: every disk in every frame
    assert frame["Points/position_mm"].shape == (n, 3)
    assert frame["PointData/radius_mm"].shape == (n,)
    start = cj.read_vtp(out / "frame_0000.vtp")["Points/position_mm"]  # before the tool has moved: the specimen
    spec = summary["specimen"]
    assert start[:, 0].min() > 0 and start[:, 0].max() < spec["width_mm"]
    assert start[:, 1].min() > 0 and start[:, 1].max() < spec["height_mm"]
    assert np.all(frame["PointData/radius_mm"] > 0.005)
    assert frame["CellData/intact_elements"].size == n + frame["Lines/connectivity"].size // 2  # disks, then joints
    walls = cj.read_vtp(out / "walls_0001.vtp")
    assert walls["Points/position_mm"].shape[0] % 2 == 0  # two ends per wall
    frames = sorted(out.glob("frame_*.vtp"))
    assert cj.main([str(out), "--zoom", "0,1", "--wide", f"0,{len(frames) - 1}", "--every", "20",
                    "--out", str(tmp_path / "jam.png")]) == 0
    assert (tmp_path / "jam.png").stat().st_size > 10000


def test_ties_follow_the_joints_from_the_held_disks():
    # 0 held, 0-1-2 joined, 3-4 joined and loose, 5 alone.
    tied = cj.tied(6, np.array([0, 1, 3]), np.array([1, 2, 4]), np.array([1, 0, 0, 0, 0, 0]))
    assert tied.tolist() == [True, True, True, False, False, False]
