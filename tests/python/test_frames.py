"""kerf.frames.tied: disks joined to a held disk by a path of joints, on a graph with a known answer."""
import numpy as np

from kerf.frames import tied


def test_a_path_of_joints_to_a_held_disk_ties_and_nothing_else_does():
    # 0 held; 0-1-2 a chain (tied); 3-4 a pair of their own (loose); 5 alone (loose); 6 held with no joint (tied).
    i, j = np.array([0, 1, 3]), np.array([1, 2, 4])
    held = [True, False, False, False, False, False, True]
    assert tied(7, i, j, held).tolist() == [True, True, True, False, False, False, True]
    # A joint from the loose pair to the chain ties it; the order of a joint's ends does not matter.
    assert tied(7, np.array([0, 1, 3, 4]), np.array([1, 2, 4, 2]), held).tolist() == [True] * 5 + [False, True]


def test_the_samples_per_frame_are_the_runs_last_override_or_none():
    from kerf.frames import samples_per_frame
    summary = {"provenance": {"overrides": ["cut.length_mm=1", "output.frame_every_samples=20",
                                            "output.frame_every_samples=60"]}}
    assert samples_per_frame(summary) == 60
    assert samples_per_frame({"provenance": {"overrides": ["cut.length_mm=1"]}}) is None
    assert samples_per_frame({"provenance": {}}) is None
