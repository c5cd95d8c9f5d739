"""analysis/cut_jam_frames.py: its ties and its figure, on a small cut's own frames."""

import numpy as np

import kerf

from repo_scripts import load

cj = load("analysis/cut_jam_frames.py")

SMALL_CUT = {"kind": "cut", "material": {"base": "soda_lime_glass_fj"},
             "specimen": {"width_mm": 0.4, "height_mm": 0.25, "radius_min_um": 10, "radius_max_um": 13, "seed": 1,
                          "growth_steps": 2000, "relax_steps": 500},
             "cut": {"depth_of_cut_mm": 0.05, "speed_m_per_s": 2, "length_mm": 0.03},
             "output": {"frame_every_samples": 20}}


def test_the_figure_is_drawn_from_a_small_cut_s_frames(tmp_path):
    out = tmp_path / "cut"
    assert kerf.dem.run(SMALL_CUT, out=out, threads=1)["exit_status"] == 0
    frames = sorted(out.glob("frame_*.vtp"))
    assert cj.main([str(out), "--zoom", "0,1", "--wide", f"0,{len(frames) - 1}", "--every", "20",
                    "--out", str(tmp_path / "jam.png")]) == 0
    assert (tmp_path / "jam.png").stat().st_size > 10000


def test_ties_follow_the_joints_from_the_held_disks():
    # 0 held, 0-1-2 joined, 3-4 joined and loose, 5 alone.
    tied = cj.tied(6, np.array([0, 1, 3]), np.array([1, 2, 4]), np.array([1, 0, 0, 0, 0, 0]))
    assert tied.tolist() == [True, True, True, False, False, False]
