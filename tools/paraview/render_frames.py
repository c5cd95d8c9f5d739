# The ParaView recipe of docs/dem.md ("ParaView and OVITO") as a pvpython script: loads a kerf-dem run's frame
# series (OUT/result.pvd), draws the disks as filled circles of their radius coloured by the magnitude of
# displacement_m (left) and by broken_joints (right), the joints as lines, the tool's faces, and the cracks
# coloured by place (1 chip, 2 subsurface), at the last frame (or frame K), and saves one PNG.
#   xvfb-run -a -s "-screen 0 1920x1080x24" pvpython tools/paraview/render_frames.py OUT picture.png [--frame K]
# Checked with ParaView 5.11 (Debian 12's paraview package) by tests/long/vtk_paraview.sh.
import argparse
import sys

from paraview.simple import (ColorBy, CreateLayout, CreateView, ExtractBlock, ExtractCellsByType, Glyph,
                             GetAnimationScene, GetColorTransferFunction, GetScalarBar, PVDReader, ResetCamera,
                             SaveScreenshot, Show)

parser = argparse.ArgumentParser(description="a kerf-dem run's frames rendered with ParaView")
parser.add_argument("run", help="the run's output directory (with result.pvd)")
parser.add_argument("png", help="the picture to write")
parser.add_argument("--frame", type=int, default=-1, help="the frame to show (default: the last)")
args = parser.parse_args()

# 1. The series: one block per part (particles, walls, cracks), one time step per frame.
series = PVDReader(FileName=f"{args.run}/result.pvd")
series.UpdatePipelineInformation()
times = list(series.TimestepValues) if series.TimestepValues else [0.0]
if not -len(times) <= args.frame < len(times):
    sys.exit(f"render_frames.py: error: --frame = {args.frame}: expected 0 .. {len(times) - 1}")
time = times[args.frame]
scene = GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
scene.AnimationTime = times[0]  # the camera is fitted to the first frame (no flying fragments yet)


def block(name):
    return ExtractBlock(Input=series, Selectors=[f"/Root/{name}"])


def filled_circles(source, scale_array, scale_factor):
    """A filled circle at every point, its diameter scale_factor times scale_array (or scale_factor alone)."""
    glyphs = Glyph(Input=source, GlyphType="2D Glyph")
    glyphs.GlyphType.GlyphType = "Circle"
    glyphs.GlyphType.Filled = 1
    glyphs.OrientationArray = ["POINTS", "No orientation array"]
    glyphs.ScaleArray = ["POINTS", scale_array]
    glyphs.ScaleFactor = scale_factor
    glyphs.GlyphMode = "All Points"
    return glyphs


particles, walls, cracks = block("particles"), block("walls"), block("cracks")
# 2. Disks: filled circles, diameter 2 * radius_mm; joints: the particle block's lines.
disks = filled_circles(particles, "radius_mm", 2.0)
joints = ExtractCellsByType(Input=particles)
joints.CellTypes = ["Line"]
# 4. Cracks: small circles of a fixed size.
crack_marks = filled_circles(cracks, "No scale array", 0.008)

layout = CreateLayout("kerf-dem frames")
layout.SplitHorizontal(0, 0.5)  # cells 1 (left) and 2 (right)
shown_frame = []
for side, (array, component, title) in enumerate([("displacement_m", "Magnitude", "displacement since frame 0 (m)"),
                                                  ("broken_joints", None, "broken joints")]):
    view = CreateView("RenderView")
    view.ViewTime = times[0]
    view.OrientationAxesVisibility = 0
    view.Background = [1, 1, 1]
    view.UseColorPaletteForBackground = 0
    layout.AssignView(1 + side, view)
    lines = Show(joints, view)  # under the disks: seen where the disks leave gaps
    ColorBy(lines, None)
    lines.AmbientColor = lines.DiffuseColor = [0.35, 0.35, 0.35]
    shown = Show(disks, view)
    ColorBy(shown, ("POINTS", array, component) if component else ("POINTS", array))
    tool = Show(walls, view)
    ColorBy(tool, None)
    tool.AmbientColor = tool.DiffuseColor = [0, 0, 0]
    tool.LineWidth = 3
    marks = Show(crack_marks, view)
    ColorBy(marks, ("POINTS", "place"))
    place = GetColorTransferFunction("place")
    place.InterpretValuesAsCategories = 1
    place.Annotations = ["1", "chip", "2", "subsurface"]
    place.IndexedColors = [0.85, 0.1, 0.1, 0.1, 0.2, 0.9]
    view.InteractionMode = "2D"
    ResetCamera(view)  # fitted to the first frame
    view.ViewTime = time
    shown_frame.append((view, shown, array, component, title))
scene.AnimationTime = time

# The colour ranges of the frame shown: displacements on a log scale from 1 nm (the flying chips move
# thousands of times more than the workpiece), broken joints 0 .. the most of a disk.
disks.UpdatePipeline(time)
for view, shown, array, component, title in shown_frame:
    lut = GetColorTransferFunction(array)
    lo, hi = disks.PointData[array].GetRange(-1 if component else 0)
    if component:
        lut.UseLogScale = 1
        lut.RescaleTransferFunction(1e-9, max(hi, 1e-8))
    else:
        lut.RescaleTransferFunction(0.0, max(hi, 1.0))
    lut.AutomaticRescaleRangeMode = "Never"
    bar = GetScalarBar(lut, view)
    bar.Title, bar.ComponentTitle = title, ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    shown.SetScalarBarVisibility(view, True)
layout.SetSize(1600, 700)
SaveScreenshot(args.png, layout, ImageResolution=[1600, 700])
print(f"render_frames.py: frame at t = {time:g} s of {args.run} -> {args.png}")
