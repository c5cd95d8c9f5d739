"""A cut's VTK frame as kerf.dem.read_frames gives it, built by hand for the tests of the frame analyses
(analysis/edge_gap_frames.py, analysis/cut_line_joints.py): disks, intact joints, held disks and a tool whose tip
(its lowest point) is at (1.0, 0.9) mm, moving towards -x."""
import numpy as np


def frame(disks, joints, held):
    """disks: [(x_mm, y_mm, r_mm)]; joints: [(i, j)] intact; held: indices of the held disks."""
    p = np.array([[x, y, 0.0] for x, y, _ in disks])
    lines = np.array(joints, dtype=int).reshape(-1, 2)
    return {"particles": {"position_mm": p, "radius_mm": np.array([r for _, _, r in disks]), "lines": lines,
                          "intact_elements": np.full(len(lines), 2),
                          "held": np.array([1 if k in held else 0 for k in range(len(disks))])},
            "walls": {"position_mm": np.array([[1.0, 0.9, 0], [1.05, 1.1, 0], [1.2, 0.95, 0]]),
                      "lines": np.array([[0, 1], [0, 2]])}}
