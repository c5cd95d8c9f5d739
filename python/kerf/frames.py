"""kerf.frames: what a cut's VTK frames (kerf.dem.read_frames) say about the glass, shared by the analysis scripts.

    from kerf.frames import samples_per_frame, steady_frames, tied, tool_tip
    every = samples_per_frame(summary)   # frame k is force sample k * every (None: the run does not say)
    frame = kerf.dem.read_frames(run_dir, steps=[k])[0]
    results, frames = steady_frames(run_dir)   # the run's summary results, its frames in the steady travel
    tip = tool_tip(frame)                      # (x, y) mm of the tool's lowest point
    joints = frame["particles"]["lines"][frame["particles"]["intact_elements"] > 0]
    on_workpiece = tied(len(frame["particles"]["radius_mm"]), joints[:, 0], joints[:, 1],
                        frame["particles"]["held"] > 0)
"""
import json
import pathlib

import numpy as np

import kerf
from kerf.result_keys import CutResults as R


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


def tool_tip(frame):
    """The tool's tip in a frame: the lowest point of its walls, (x, y) in mm."""
    w = frame["walls"]["position_mm"][:, :2]
    return w[np.argmin(w[:, 1])]


def steady_frames(folder):
    """(the run's summary results, [its frames in the steady travel]) of a cut's output folder written with
    output.frame_every_samples > 0: frame k is force sample k * every (the last sample where the frames run past
    them), steady from the results' steady_from_travel_mm. ValueError naming the folder where the run does not say
    its frames' interval."""
    folder = pathlib.Path(folder)
    summary = json.loads((folder / "summary.json").read_text())
    every = samples_per_frame(summary)
    if every is None:
        raise ValueError(f"{folder}: the run does not say its output.frame_every_samples "
                         "(run it with --set output.frame_every_samples=N)")
    results = summary["results"]
    travel = np.loadtxt(folder / "forces.csv", delimiter=",", skiprows=1)[:, 0]
    frames = kerf.dem.read_frames(folder)
    return results, [f for k, f in enumerate(frames)
                     if travel[min(k * every, len(travel) - 1)] >= results[R.steady_from_travel_mm]]
