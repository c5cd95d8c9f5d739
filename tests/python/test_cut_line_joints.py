"""analysis/cut_line_joints.py: the two criteria for intact glass at the edge, on frames with a known answer."""
from cut_frames import frame
from repo_scripts import load

cl = load("analysis/cut_line_joints.py")

Y_CUT = 0.9
REACH = 0.026  # mm


# 0: held, deep; 1: straddles the line ahead of the tip (centre 5 um below it), 20 um ahead; 2: above the line,
# 20 um ahead; 3: below the line, far ahead (0.2 mm); 4: above the line far ahead.
DISKS = [(0.5, 0.5, 0.01), (0.98, 0.895, 0.01), (0.98, 0.915, 0.01), (0.8, 0.89, 0.01), (0.8, 0.91, 0.01)]


def test_intact_glass_across_the_line_meets_both_criteria():
    f = frame(DISKS, [(0, 1), (1, 2)], held={0})
    assert cl.criteria(f, Y_CUT, REACH) == (True, True)


def test_a_crack_along_the_line_leaves_a_straddling_disk_but_no_joint_across():
    # The joint 1-2 broken: the glass above the path is free, the disk below still straddles the line, joined to a
    # disk below it within the reach (a joint that does not cross the line).
    disks = DISKS + [(0.98, 0.875, 0.01)]
    f = frame(disks, [(0, 5), (5, 1)], held={0})
    assert cl.criteria(f, Y_CUT, REACH) == (True, False)


def test_a_loose_lower_disk_or_a_joint_out_of_reach_counts_for_neither():
    assert cl.criteria(frame(DISKS, [(1, 2)], held={0}), Y_CUT, REACH) == (False, False)
    # Joined across the line, but 0.2 mm ahead: beyond the reach.
    assert cl.criteria(frame(DISKS, [(0, 3), (3, 4)], held={0}), Y_CUT, REACH) == (False, False)
    # ... and within a reach of 0.25 mm.
    assert cl.criteria(frame(DISKS, [(0, 3), (3, 4)], held={0}), Y_CUT, 0.25)[1]


def test_a_joint_behind_the_tip_is_not_ahead():
    disks = [(0.5, 0.5, 0.01), (1.01, 0.895, 0.01), (1.01, 0.915, 0.01)]
    assert cl.criteria(frame(disks, [(0, 1), (1, 2)], held={0}), Y_CUT, REACH)[1] is False
