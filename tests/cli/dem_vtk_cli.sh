#!/usr/bin/env bash
# kerf-dem's VTK frames (issue 23 item 5) read back with the VTK library (python3-vtk9): binary (appended
# raw) PolyData; the disks with id, radius_mm, group and held; the joints as lines; the tool's faces as their
# own part (walls_NNNN.vtp); the crack events as points equal to cracks.csv; result.pvd listing the three
# parts of every frame by name; positions in mm like the CSVs (issue 40 item 9:) each disk's displacement_m since
# the first frame and its broken_joints, each crack's place as in cracks.csv, a PNG per frame with
# output.frame_png; in a windowed cut, id the workpiece index and displacements that follow each disk across frames.
# Usage: dem_vtk_cli.sh <dir of built programs> <source dir>
source "$(dirname "$0")/lib/dem_common.sh" "$@"

python=""
for candidate in python3 /usr/bin/python3; do
  if command -v "$candidate" >/dev/null && "$candidate" -c "import vtk" 2>/dev/null; then python="$candidate"; break; fi
done
[ -n "$python" ] || fail "no Python 3 with the vtk module (Debian: python3-vtk9, scripts/install-deps.sh)"

scene="$src/data/scenes/dem_cut.json"
small=(--set specimen.width_mm=0.4 --set specimen.height_mm=0.25 --set specimen.growth_steps=2000
       --set specimen.relax_steps=500 --set cut.depth_of_cut_mm=0.05 --set cut.length_mm=0.08
       --set output.frame_every_samples=40 --set cut.speed_m_per_s=2 --set output.frame_png=true)
"$bin" run "$scene" "${small[@]}" --threads 1 --out "$work/c" >/dev/null 2>"$work/err" || fail "cut run: $(cat "$work/err")"
! grep -q 'format="ascii"' "$work/c"/*.vtp || fail "an ASCII array in a frame"
"$python" - "$work/c" <<'PY' || fail "the frames read back with VTK differ from the run"
import csv, json, sys, xml.etree.ElementTree as ET
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy as np_of

out = sys.argv[1]
summary = json.load(open(f"{out}/summary.json"))
n = summary["n_particles"]
sets = ET.parse(f"{out}/result.pvd").getroot().findall("./Collection/DataSet")
frames = sorted({d.get("timestep") for d in sets}, key=float)
assert len(frames) >= 2, frames
for d in sets:  # every frame: part 0 the disks, 1 the walls, 2 the cracks
    part, name, file = int(d.get("part")), d.get("name"), d.get("file")
    assert (part, name) in {(0, "particles"), (1, "walls"), (2, "cracks")}, (part, name)
    assert file.startswith({0: "frame_", 1: "walls_", 2: "cracks_"}[part]), file
last = {int(d.get("part")): d.get("file") for d in sets if d.get("timestep") == frames[-1]}

def place_ok(cracks, rows):
    """The crack frame's place codes (1 chip, 2 subsurface) row by row as cracks.csv's place column."""
    place = np_of(cracks.GetPointData().GetArray("place"))
    codes = [{"chip": 1, "subsurface": 2}[row["place"]] for row in rows]
    assert list(place) == codes, (list(place)[:10], codes[:10])
    assert {1, 2} <= set(codes), "a cut with cracks in the chip and below the cut line expected"
    return True

def read(name):
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(f"{out}/{name}")
    r.Update()
    assert r.GetErrorCode() == 0, name
    return r.GetOutput()

disks = read(last[0])
assert disks.GetNumberOfPoints() == n, (disks.GetNumberOfPoints(), n)
pd = disks.GetPointData()
ids = np_of(pd.GetArray("id"))
assert (ids == range(n)).all()
radius = np_of(pd.GetArray("radius_mm"))
spec = summary["specimen"]
# Radii in mm (the specimen's radius range is in um; genesis scales it a little).
r_lo, r_hi = (spec[k] / 1000 for k in ("radius_min_um", "radius_max_um"))
assert 0.8 * r_lo <= radius.min() and radius.max() <= 1.25 * r_hi, (radius.min(), radius.max(), r_lo, r_hi)
held = np_of(pd.GetArray("held"))
group = np_of(pd.GetArray("group"))
assert held.sum() > 0 and ((group > 0) == (held == 1)).all()
xy = np_of(disks.GetPoints().GetData())
# Positions in mm: the workpiece spans about specimen.width_mm.
assert 0.5 * spec["width_mm"] < xy[:, 0].max() - xy[:, 0].min() < 2 * spec["width_mm"] + 1, xy[:, 0].ptp()
assert disks.GetNumberOfVerts() == n and disks.GetNumberOfLines() > 0
intact = np_of(disks.GetCellData().GetArray("intact_elements"))
assert (intact[:n] == -1).all() and (intact[n:] >= 0).all() and intact[n:].max() >= 1
# Force chains (issue 55 item 6): each disk's stress tensor (symmetric, z row and column 0), its pressure, the sum
# of the forces on it; each joint's normal and shear force (0 on the disks' vertex cells). The joints' normal forces
# bound the disks' sums from below: a disk's sum holds at least its largest joint's force.
stress = np_of(pd.GetArray("stress_MPa"))
assert stress.shape == (n, 9), stress.shape
assert (stress[:, 1] == stress[:, 3]).all() and (stress[:, [2, 5, 6, 7, 8]] == 0).all()
pressure = np_of(pd.GetArray("pressure_MPa"))
assert np.allclose(pressure, -0.5 * (stress[:, 0] + stress[:, 4]), rtol=1e-12, atol=1e-12 * abs(stress).max())
force_sum = np_of(pd.GetArray("contact_force_sum_N"))
assert (force_sum >= 0).all() and (force_sum > 0).mean() > 0.5, (force_sum > 0).mean()
cd = disks.GetCellData()
normal, shear = (np_of(cd.GetArray(k)) for k in ("joint_normal_force_N", "joint_shear_force_N"))
assert normal.shape == shear.shape == (disks.GetNumberOfCells(),)
assert (normal[:n] == 0).all() and (shear[:n] == 0).all() and (normal[n:] != 0).mean() > 0.5
lines = np_of(disks.GetLines().GetConnectivityArray()).reshape(-1, 2)
largest = np.zeros(n)
for (i, j), f, s in zip(lines, normal[n:], shear[n:]):
    largest[i] = max(largest[i], np.hypot(f, s)); largest[j] = max(largest[j], np.hypot(f, s))
assert (force_sum >= largest * (1 - 1e-9)).all(), "a disk's force sum below one of its joints' forces"
# Stress of the scale of its forces: |sigma| <= sum |f| r / (pi r^2 t) per disk (t = the specimen's thickness).
t_mm = spec.get("thickness_mm", 1.0)
bound = force_sum / (np.pi * radius * t_mm)  # N/mm^2 = MPa
assert (np.abs(stress[:, [0, 4, 1]]).max(axis=1) <= bound * (1 + 1e-9)).all()

walls = read(last[1])
assert walls.GetNumberOfLines() >= 2 and walls.GetNumberOfPoints() == 2 * walls.GetNumberOfLines()
assert walls.GetCellData().GetArray("force_N").GetNumberOfComponents() == 3
wxy = np_of(walls.GetPoints().GetData())
assert abs(wxy[:, 1].max() - xy[:, 1].max()) < 1, "the tool is not near the workpiece (mm)"

cracks = read(last[2])
rows = list(csv.DictReader(open(f"{out}/cracks.csv")))
assert cracks.GetNumberOfPoints() == len(rows) > 0, (cracks.GetNumberOfPoints(), len(rows))
cxy = np_of(cracks.GetPoints().GetData())
mode = np_of(cracks.GetPointData().GetArray("mode"))
length = np_of(cracks.GetPointData().GetArray("length_um"))
for k, row in enumerate(rows):
    assert abs(cxy[k, 0] - float(row["x_mm"])) <= 1e-12 * max(1, abs(cxy[k, 0])), (k, cxy[k], row)
    assert abs(cxy[k, 1] - float(row["y_mm"])) <= 1e-12 * max(1, abs(cxy[k, 1])), (k, cxy[k], row)
    assert mode[k] == {"tension": 1, "shear": 2}[row["mode"]], (k, mode[k], row["mode"])
    assert abs(length[k] - float(row["length_um"])) <= 1e-9 * length[k], (k, length[k], row)
assert place_ok(cracks, rows)

# Every frame: the same disks (id), displacement_m = position - position at the first frame (z = 0; zero in
# the first frame), broken_joints per disk up by as many as the disk's joints (lines) went down.
def lines_per_disk(frame):
    cells = np_of(frame.GetLines().GetData()).reshape(-1, 3)  # (2, i, j) per line
    return np.bincount(cells[:, 1:].ravel(), minlength=frame.GetNumberOfPoints())

first = read(sorted(d.get("file") for d in sets if d.get("part") == "0")[0])
xy0 = np_of(first.GetPoints().GetData())
lines0, broken0 = lines_per_disk(first), np_of(first.GetPointData().GetArray("broken_joints"))
moved = False
for d in sets:
    if d.get("part") != "0":
        continue
    frame = read(d.get("file"))
    fd = frame.GetPointData()
    assert (np_of(fd.GetArray("id")) == np.arange(n)).all(), d.get("file")
    disp = np_of(fd.GetArray("displacement_m"))
    assert disp.shape == (n, 3) and (disp[:, 2] == 0).all(), disp.shape
    expected = (np_of(frame.GetPoints().GetData()) - xy0) / 1000  # mm -> m
    assert np.abs(disp - expected).max() <= 1e-15, (d.get("file"), np.abs(disp - expected).max())
    if frame.GetPointData().GetArray("broken_joints") is None:
        raise AssertionError("no broken_joints")
    broken = np_of(fd.GetArray("broken_joints"))
    assert ((broken - broken0) == (lines0 - lines_per_disk(frame))).all(), d.get("file")
    assert broken.sum() % 2 == 0
    moved = moved or np.abs(disp).max() > 1e-7
assert (np_of(first.GetPointData().GetArray("displacement_m")) == 0).all()
assert moved, "no disk moved 0.1 um in the whole cut"
assert broken.sum() > broken0.sum(), "no joint broke in the cut"

# A PNG per frame (output.frame_png).
for d in sets:
    if d.get("part") == "0":
        png = f"{out}/{d.get('file')[:-4]}.png"
        assert open(png, "rb").read(8) == b"\x89PNG\r\n\x1a\n", png
print("vtk frames: ok")
PY
# A windowed cut (active window, rebuilt as the tool travels): each frame's disks are the running window's,
# `id` their index in the workpiece; displacements follow each disk across frames (also one that entered the
# window after the first frame: the workpiece's reference holds every disk).
"$bin" run "$scene" "${small[@]/specimen.width_mm=0.4/specimen.width_mm=0.8}" --set cut.length_mm=0.15 \
    --set active_window.enabled=true --set output.frame_png=false --threads 1 --out "$work/w" >/dev/null 2>"$work/err" ||
  fail "windowed cut run: $(cat "$work/err")"
"$python" - "$work/w" <<'PY' || fail "the windowed cut's frames (above)"
import json, sys, xml.etree.ElementTree as ET
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy as np_of

out = sys.argv[1]
assert json.load(open(f"{out}/summary.json"))["active_window"]["rebuilds"] >= 2
files = sorted(d.get("file") for d in ET.parse(f"{out}/result.pvd").getroot().findall("./Collection/DataSet")
               if d.get("part") == "0")
frames = []
for name in files:
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(f"{out}/{name}")
    r.Update()
    pd = r.GetOutput().GetPointData()
    ids = np_of(pd.GetArray("id"))
    assert len(np.unique(ids)) == len(ids), name
    frames.append({int(i): (xy, d) for i, xy, d in zip(ids, np_of(r.GetOutput().GetPoints().GetData()),
                                                       np_of(pd.GetArray("displacement_m")))})
assert all((d == 0).all() for _, d in frames[0].values())
entered = 0
for k, frame in enumerate(frames[1:], 1):
    for i, (xy, d) in frame.items():
        assert np.isfinite(d).all(), (files[k], i)
        for j in (0, k - 1):  # against the first frame and the one before
            if i in frames[j]:
                xy_j, d_j = frames[j][i]
                assert np.abs((d - d_j) - (xy - xy_j) / 1000).max() <= 1e-15, (files[k], i, j)
        entered += i not in frames[0]
assert entered > 0, "no disk entered the window after the first frame"
print("windowed frames: ok")
PY
echo "dem vtk: ok"
