"""kerf.frames: what a cut's VTK frames (kerf.dem.read_frames) say about the glass, shared by the analysis scripts.

    from kerf.frames import samples_per_frame, tied
    every = samples_per_frame(summary)   # frame k is force sample k * every (None: the run does not say)
    frame = kerf.dem.read_frames(run_dir, steps=[k])[0]
    joints = frame["particles"]["lines"][frame["particles"]["intact_elements"] > 0]
    on_workpiece = tied(len(frame["particles"]["radius_mm"]), joints[:, 0], joints[:, 1],
                        frame["particles"]["held"] > 0)
"""
import numpy as np


def tied(n, i, j, held):
    """Per disk of n: whether a path of the joints (i[k], j[k]) joins it to a held disk ("tied" to the workpiece, as
    the cut's own measures count it; a disk with no such path is loose: chip, debris, rubble)."""
    neighbours = [[] for _ in range(n)]
    for a, b in zip(i, j):
        neighbours[a].append(b)
        neighbours[b].append(a)
    out = np.array(held, dtype=bool)
    queue = list(np.flatnonzero(out))
    while queue:
        for v in neighbours[queue.pop()]:
            if not out[v]:
                out[v] = True
                queue.append(v)
    return out


def samples_per_frame(summary):
    """The force samples between a run's frames: its override of output.frame_every_samples, as its summary's
    provenance records it (None when the run did not set one)."""
    given = [o.split("=", 1)[1] for o in summary["provenance"].get("overrides", [])
             if o.startswith("output.frame_every_samples=")]
    return int(given[-1]) if given else None
