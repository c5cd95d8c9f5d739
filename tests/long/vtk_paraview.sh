#!/usr/bin/env bash
# The ParaView recipe checked with ParaView itself (issue 40 item 9): a small cut with frames, then ParaView's
# own Python (pvpython, Debian's paraview package 5.11, under a virtual X server) runs the docs' recipe
# (tools/paraview/render_frames.py: result.pvd loaded, the disks coloured by the magnitude of displacement_m
# and by broken_joints, the joints, the tool, the cracks coloured by place) and renders a PNG, which must exist
# and not be blank: many colours, the colour maps' among them; then ParaView's reader finds the force-chain
# arrays. Labelled "long" (ParaView is a large package: scripts/install-deps.sh --long installs it;
# scripts/test.sh --long passes that). KERF_PARAVIEW_PNG=FILE keeps a copy of the picture.
# Usage: vtk_paraview.sh <dir of built programs> <source dir>
source "$(dirname "$0")/../cli/lib/dem_common.sh" "$@"

for tool in pvpython xvfb-run xauth; do  # Debian: pvpython is python3-paraview's
  command -v "$tool" >/dev/null || fail "no $tool (Debian: paraview python3-paraview xvfb xauth; bash scripts/install-deps.sh --long)"
done

scene="$src/data/scenes/dem_cut.json"
small=(--set specimen.width_mm=0.4 --set specimen.height_mm=0.25 --set specimen.growth_steps=2000
       --set specimen.relax_steps=500 --set cut.depth_of_cut_mm=0.05 --set cut.length_mm=0.08
       --set output.frame_every_samples=40 --set cut.speed_m_per_s=2)
"$bin" run "$scene" "${small[@]}" --threads "${KERF_LONG_THREADS:-1}" --out "$work/c" >/dev/null 2>"$work/err" ||
  fail "cut run: $(cat "$work/err")"
# A 24-bit screen (the default 8 bits has no OpenGL visual). On a loaded machine pvpython sometimes meets a
# virtual X server not ready yet ("bad X server connection"): that alone is tried again, twice.
for attempt in 1 2 3; do
  xvfb-run -a -s "-screen 0 1920x1080x24" pvpython "$src/tools/paraview/render_frames.py" "$work/c" "$work/frames.png" \
    >"$work/pv.out" 2>&1 && break
  grep -q "bad X server connection" "$work/pv.out" && [ $attempt -lt 3 ] ||
    fail "pvpython: $(grep -v '^ *[0-9]* *0x' "$work/pv.out" | tail -20)"
  echo "pvpython could not connect to the virtual X server (attempt $attempt): again" >&2
done
[ -s "$work/frames.png" ] || fail "pvpython wrote no picture: $(tail -20 "$work/pv.out")"
[ -z "${KERF_PARAVIEW_PNG:-}" ] || cp "$work/frames.png" "$KERF_PARAVIEW_PNG"
python=""
for candidate in python3 /usr/bin/python3; do
  "$candidate" -c "import numpy, matplotlib" 2>/dev/null && { python="$candidate"; break; }
done
[ -n "$python" ] || fail "no Python 3 with numpy and matplotlib (Debian: python3-numpy python3-matplotlib)"
"$python" - "$work/frames.png" <<'PY' || fail "the ParaView picture is blank or flat (above)"
import sys
import numpy as np
import matplotlib.image

rgb = (matplotlib.image.imread(sys.argv[1])[:, :, :3] * 255).round().astype(np.uint8)
h, w, _ = rgb.shape
assert (h, w) == (700, 1600), (h, w)
for name, half in (("left (displacement)", rgb[:, : w // 2]), ("right (broken joints)", rgb[:, w // 2 :])):
    colours = np.unique(half.reshape(-1, 3), axis=0)
    # Not blank: the white background, grey joints, black tool and a colour map's many shades.
    assert len(colours) > 50, f"{name}: {len(colours)} colours"
    background = (half == 255).all(axis=2).mean()
    assert 0.05 < background < 0.98, f"{name}: {background:.2%} white"
    # Coloured pixels (not grey): the colour map.
    spread = half.max(axis=2).astype(int) - half.min(axis=2)
    assert (spread > 60).mean() > 0.01, f"{name}: almost no coloured pixels"
print(f"ParaView picture {w} x {h}: ok")
PY
# ParaView's own reader finds the force-chain arrays (issue 55 item 6): each disk's stress tensor, pressure and
# force sum, each joint's normal and shear force (of both signs in a cut).
cat >"$work/chains.py" <<'PVPY'
import sys
from paraview.simple import PVDReader, servermanager
reader = PVDReader(FileName=f"{sys.argv[1]}/result.pvd")
reader.UpdatePipeline(max(reader.TimestepValues))
data = servermanager.Fetch(reader)
while not hasattr(data, "GetPointData"):  # the particles part: the first block, down to its data set
    data = data.GetBlock(0)
points, cells = data.GetPointData(), data.GetCellData()
for name in ("stress_MPa", "pressure_MPa", "contact_force_sum_N"):
    assert points.GetArray(name) is not None, name
assert points.GetArray("stress_MPa").GetNumberOfComponents() == 9
for name in ("joint_normal_force_N", "joint_shear_force_N"):
    array = cells.GetArray(name)
    assert array is not None and array.GetRange()[0] < 0 < array.GetRange()[1], (name, array and array.GetRange())
print("ParaView reads the force-chain arrays")
PVPY
xvfb-run -a pvpython "$work/chains.py" "$work/c" >"$work/pv_chains.out" 2>&1 ||
  fail "pvpython, force chains: $(grep -v '^ *[0-9]* *0x' "$work/pv_chains.out" | tail -10)"
echo "vtk_paraview: ok"
