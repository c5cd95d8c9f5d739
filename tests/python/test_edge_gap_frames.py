"""analysis/edge_gap_frames.py: the gap from the tool's tip to the tied glass at the cut line, on a frame with a known
answer."""
import math

import numpy as np
from cut_frames import frame
from repo_scripts import load

eg = load("analysis/edge_gap_frames.py")


def test_the_nearest_tied_disk_on_the_cut_line_ahead_sets_the_gap():
    y_cut = 0.9
    disks = [(0.5, 0.5, 0.01),           # 0: held, deep
             (0.95, 0.905, 0.01),        # 1: tied through 0, straddles the line, 40 um from the tip to its near side
             (0.985, 0.9, 0.01),         # 2: loose (no joint), closer: not the glass
             (0.975, 0.93, 0.01),        # 3: tied, closer, but above the line (|y - y_cut| > r): not at the line
             (1.1, 0.9, 0.01)]           # 4: tied, at the line, behind the tip
    f = frame(disks, [(0, 1), (0, 3), (0, 4)], held={0})
    assert math.isclose(eg.gap_um(f, y_cut), 1e3 * (1.0 - 0.96), rel_tol=1e-9)
    # Tie disk 2 and it is the nearest; no tied disk at the line ahead: no gap (inf).
    f = frame(disks, [(0, 1), (0, 3), (0, 4), (1, 2)], held={0})
    assert math.isclose(eg.gap_um(f, y_cut), 1e3 * (1.0 - 0.995), rel_tol=1e-9)
    assert eg.gap_um(frame(disks, [(0, 3), (0, 4)], held={0}), y_cut) == math.inf


def test_the_shares_count_gaps_within_each_reach():
    text = eg.describe("run", np.array([-1.0, 3.0, 20.0, 100.0, np.inf]))
    assert "5 frames" in text and "within 0 um 20.0%" in text and "within 5 um 40.0%" in text
    assert "within 26 um 60.0%" in text and "none ahead in 20%" in text
