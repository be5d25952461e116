"""A hybrid run directory in ParaView, off-screen: the grains of its last VTK snapshot as discs of
their radii, with their contacts' normal forces as line width, over the host's in-plane von Mises
stress (host_field.vtu), the body's outline (host_boundary.vtp) and the cavity's boundary
particles (host_particles.csv), saved as a PNG. The host is drawn displaced (true scale), where
the grains are.

  pvpython tools/paraview_render.py RUNDIR OUT.png [--size W H] [--colours N] [--report R.json]

Debian's ParaView (tools/setup.sh --with-paraview) renders through X only: without a display it
aborts ("bad X server connection"), even with --force-offscreen-rendering. Without $DISPLAY this
script starts an Xvfb of its own for the run (-noreset: see virtual_display).
--report writes what ParaView read and drew (counts, radii, ranges, the camera) for ctest
demo_paraview_render (tests/paraview/test_paraview.py), which checks it and the picture against the
run's own files.
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys

from paraview import servermanager
from paraview.simple import (Calculator, CellDatatoPointData, Clean, Clip, ColorBy, CreateRenderView, CSVReader, Disk,
                             ExtractSurface, GetColorTransferFunction, GetScalarBar, GlyphWithCustomSource,
                             PVDReader, Render, SaveScreenshot, Show, TableToPoints, Text, Threshold, Transform, Tube,
                             WarpByVector, XMLPolyDataReader, XMLUnstructuredGridReader)
from vtkmodules.util.numpy_support import vtk_to_numpy

GRAIN = [0.82, 0.82, 0.82]     # the discs' fill: a grey that the stress's colour map (viridis) does not hold
PARTICLE = [0.55, 0.55, 0.55]  # the boundary particles' fill
RING = 0.92                    # the discs' dark rim spans RING r to r
TUBE = 0.2                     # the contact line of the largest normal force: its half width over the mean radius
MARGIN = 40                    # pixels left of the body; the colour bar goes right of it


def virtual_display():
    """Without $DISPLAY, an Xvfb server for this run (None with one). Xvfb picks a free display
    and writes its number once it accepts clients (-displayfd: no race between parallel runs);
    -noreset, because an X server resets when its last client leaves and refuses connections
    meanwhile: pvpython connects more than once, and without it 1 run of 16 of `xvfb-run -a
    pvpython` aborted here ("bad X server connection"), 0 of 16 with it."""
    if os.environ.get("DISPLAY"):
        return None
    xvfb = shutil.which("Xvfb")
    if not xvfb:
        print("paraview_render: no display and no Xvfb (Debian's pvpython renders through X): "
              "tools/setup.sh --with-paraview installs it", file=sys.stderr)
        sys.exit(2)
    r, w = os.pipe()
    server = subprocess.Popen([xvfb, "-displayfd", str(w), "-screen", "0", "1920x1200x24", "-nolisten", "tcp",
                               "-noreset"], pass_fds=(w,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(w)
    with os.fdopen(r) as f:
        number = f.readline().strip()
    if not number:
        print(f"paraview_render: Xvfb did not start (exit {server.wait()})", file=sys.stderr)
        sys.exit(1)
    os.environ["DISPLAY"] = ":" + number
    return server


def fetch(proxy, time=None):
    proxy.UpdatePipeline() if time is None else proxy.UpdatePipeline(time)
    return servermanager.Fetch(proxy)


def point_array(data, name):
    return vtk_to_numpy(data.GetPointData().GetArray(name))


def units(rundir):
    """The scene's stress unit, force/length^2, from its copy in the run directory (or '')."""
    try:
        import yaml
        with open(os.path.join(rundir, "scene.yaml")) as f:
            u = yaml.safe_load(f).get("units", {})
        return f" [{u['force']}/{u['length']}^2]"
    except (ImportError, OSError, KeyError, AttributeError, TypeError):
        return ""


def flat(display, color=None):
    """Colours as given (or the colour map's), unshaded: the test reads them back from the picture."""
    display.Ambient, display.Diffuse, display.Specular = 1.0, 0.0, 0.0
    if color:
        display.ColorArrayName = ["POINTS", ""]
        display.AmbientColor = display.DiffuseColor = color
    return display


def lifted(source, dz):
    """The source moved up by dz towards the camera, so that it is drawn over what lies at z = 0."""
    t = Transform(Input=source)
    t.Transform.Translate = [0, 0, dz]
    return t


def glyphs(points, shape, scale, orientation=None):
    """SHAPE (of size 1) on every point (ParaView's default glyphs only a spatial sample of them),
    scaled by the SCALE array: a unit disc becomes a disc of radius SCALE."""
    g = GlyphWithCustomSource(Input=points, GlyphSource=shape)
    g.GlyphMode, g.ScaleArray, g.ScaleFactor = "All Points", ["POINTS", scale], 1.0
    g.OrientationArray = ["POINTS", orientation or "No orientation array"]
    return g


def unit_disc(inner=0.0):
    return Disk(InnerRadius=inner, OuterRadius=1.0, CircumferentialResolution=96)


def particles(rundir):
    """The boundary particles: half-discs of radius r on the cavity elements' displaced midpoints,
    bulging along the body's outward normal (into the cavity)."""
    table = CSVReader(FileName=[os.path.join(rundir, "host_particles.csv")])
    pts = TableToPoints(Input=table, XColumn="x", YColumn="y", ZColumn="x", a2DPoints=1)
    moved = Calculator(Input=pts, CoordinateResults=1, Function="(coordsX+ux)*iHat+(coordsY+uy)*jHat")
    normal = Calculator(Input=moved, ResultArrayName="normal", Function="nx*iHat+ny*jHat")
    half = Clip(Input=unit_disc(), ClipType="Plane", Invert=0)  # the half x >= 0, turned along the normal
    half.ClipType.Origin, half.ClipType.Normal = [0, 0, 0], [1, 0, 0]
    return glyphs(normal, ExtractSurface(Input=half), "r", "normal"), normal


def few_colours(path, n):
    """The picture in N colours, dithered (a smaller file for docs/; PIL comes with matplotlib)."""
    from PIL import Image
    im = Image.open(path).convert("RGB")
    palette = im.quantize(n, method=Image.Quantize.FASTOCTREE)
    im.quantize(palette=palette, dither=Image.Dither.FLOYDSTEINBERG).save(path, optimize=True)


def render(rundir, out, size, report_path, colours=None):
    snapshots, host = "output.snapshot_every or snapshot_steps writes it", "a hybrid run writes it at its end"
    for f, why in (("steps.csv", "every run writes it"), ("grains.pvd", snapshots), ("contacts.pvd", snapshots),
                   ("host_field.vtu", host), ("host_boundary.vtp", host), ("host_particles.csv", host)):
        if not os.path.isfile(os.path.join(rundir, f)):
            print(f"paraview_render: {rundir}/{f} is missing ({why})", file=sys.stderr)
            sys.exit(2)
    grains = PVDReader(FileName=os.path.join(rundir, "grains.pvd"))
    step = list(grains.TimestepValues or [0.0])[-1]
    with open(os.path.join(rundir, "steps.csv")) as f:
        last = float(f.readlines()[-1].split(",")[0])  # the host's files are of the run's end
    if step != last:
        print(f"paraview_render: warning: the last snapshot is of step {step:g}, the host's field of step {last:g} "
              "(output.snapshot_steps: add the last step)", file=sys.stderr)
    g = fetch(grains, step)
    n = g.GetNumberOfPoints()
    xy = vtk_to_numpy(g.GetPoints().GetData())[:, :2]
    radius = point_array(g, "radius")
    rmean = float(radius.mean())
    fill, rim = glyphs(grains, unit_disc(), "radius"), glyphs(grains, unit_disc(RING), "radius")
    d = fetch(fill, step)
    per = d.GetNumberOfPoints() // max(n, 1)  # each disc's points, glyph after glyph
    pts = vtk_to_numpy(d.GetPoints().GetData())[:, :2].reshape(n, per, 2)
    glyph_r = [max(math.dist(c, p) for p in q) for c, q in zip(xy, pts)]

    # The host, displaced: its interior field, and its boundary by the mean displacement of the two
    # elements at each node (constant elements: per element, its ends would part).
    field = WarpByVector(Input=XMLUnstructuredGridReader(FileName=[os.path.join(rundir, "host_field.vtu")]),
                         Vectors=["POINTS", "displacement"], ScaleFactor=1.0)
    h = fetch(field)
    vm = point_array(h, "von_mises_inplane")
    lo, hi = float(vm.min()), float(vm.max())
    nodes = Clean(Input=XMLPolyDataReader(FileName=[os.path.join(rundir, "host_boundary.vtp")]))
    outline = WarpByVector(Input=CellDatatoPointData(Input=nodes), Vectors=["POINTS", "displacement"], ScaleFactor=1.0)
    x0, x1, y0, y1, _, _ = fetch(outline).GetBounds()
    bp, bp_points = particles(rundir)
    n_particles = fetch(bp_points).GetNumberOfPoints()

    # Contacts (grain-grain, grain-particle; not the box's outline, kind 2) as tubes, radius
    # growing linearly with pn from TUBE / 10 to TUBE (of the mean grain radius).
    real = Threshold(Input=PVDReader(FileName=os.path.join(rundir, "contacts.pvd")), Scalars=["CELLS", "kind"],
                     LowerThreshold=0, UpperThreshold=1, ThresholdMethod="Between")
    n_contacts = fetch(real, step).GetNumberOfCells()
    tubes = Tube(Input=CellDatatoPointData(Input=ExtractSurface(Input=real)), Scalars=["POINTS", "pn"],
                 VaryRadius="By Scalar", Radius=0.1 * TUBE * rmean, RadiusFactor=10.0, NumberofSides=12)

    view = CreateRenderView()
    view.ViewSize, view.ViewTime = list(size), step
    view.OrientationAxesVisibility, view.UseColorPaletteForBackground, view.Background = 0, 0, [1, 1, 1]
    fd = flat(Show(field, view))
    ColorBy(fd, ("POINTS", "von_mises_inplane"))
    lut = GetColorTransferFunction("von_mises_inplane")
    lut.ApplyPreset("Viridis (matplotlib)", True)
    lut.RescaleTransferFunction(lo, hi)
    fd.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)
    bar.Title, bar.ComponentTitle = "host: in-plane von Mises stress" + units(rundir), ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    bar.TitleFontSize, bar.LabelFontSize, bar.RangeLabelFormat = 18, 16, "%.4g"
    bar.WindowLocation, bar.ScalarBarLength = "Any Location", 0.72
    top = 2 * float(radius.max())  # above the discs
    flat(Show(bp, view), PARTICLE)
    flat(Show(fill, view), GRAIN)
    flat(Show(lifted(rim, 0.1 * top), view), [0.25, 0.25, 0.25])
    flat(Show(lifted(tubes, top), view), [0.05, 0.05, 0.05])
    flat(Show(lifted(outline, top), view), [0, 0, 0]).LineWidth = 2.0
    title = Text(Text=f"{os.path.basename(os.path.abspath(rundir))}, step {step:g}"
                      f"{'' if step == last else f' (host: step {last:g})'}: {n} grains (discs of their "
                      f"radii), {n_contacts} contacts (width grows with the normal force)\nover the host's in-plane "
                      "von Mises stress (host_field.vtu; white: outside its grid), host displaced at true scale")
    td = Show(title, view)
    td.WindowLocation, td.FontSize, td.Color = "Upper Center", 15, [0, 0, 0]

    Render(view)  # the first render resets the camera: set it after
    # Parallel projection: the body fills the height less a margin, MARGIN pixels from the left.
    w, hgt = size
    scale = 0.5 * (y1 - y0) * 1.22
    ppu = hgt / (2 * scale)  # pixels per unit length
    focal = [x0 + (w / 2 - MARGIN) / ppu, 0.5 * (y0 + y1) + 0.05 * (y1 - y0), 0.0]
    bar.Position = [min((MARGIN + (x1 - x0) * ppu + 50) / w, 0.85), 0.12]  # 50 pixels right of the body
    view.CameraParallelProjection, view.CameraViewUp = 1, [0, 1, 0]
    view.CameraFocalPoint, view.CameraPosition = focal, [focal[0], focal[1], 100 * (x1 - x0 + y1 - y0)]
    view.CameraParallelScale = scale
    SaveScreenshot(out, view, ImageResolution=list(size), TransparentBackground=0)
    if colours:
        few_colours(out, colours)
    print(f"{out}: {n} grains at step {step:g}, {n_contacts} contacts, {n_particles} boundary particles, host field "
          f"{h.GetNumberOfPoints()} points, in-plane von Mises stress {lo:.4g} to {hi:.4g}")
    if report_path:
        with open(report_path, "w") as f:
            json.dump({"step": step, "host_step": last, "grains": n, "x": xy[:, 0].tolist(), "y": xy[:, 1].tolist(),
                       "radius": radius.tolist(), "glyph_radius": glyph_r, "contacts": n_contacts,
                       "particles": n_particles, "field_points": h.GetNumberOfPoints(),
                       "field_cells": h.GetNumberOfCells(), "von_mises_range": [lo, hi],
                       "color_range": [lut.RGBPoints[0], lut.RGBPoints[-4]],
                       "finite": bool(all(math.isfinite(v) for v in vm)), "image_size": list(size),
                       "focal_point": focal[:2], "parallel_scale": scale, "grain_color": GRAIN,
                       "tube_radius": TUBE * rmean}, f, indent=1)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("rundir")
    p.add_argument("out")
    p.add_argument("--size", type=int, nargs=2, default=[1000, 800], metavar=("W", "H"))
    p.add_argument("--report")
    p.add_argument("--colours", type=int, help="save the picture in so many colours (at most 256), dithered")
    a = p.parse_args()
    server = virtual_display()
    try:
        render(a.rundir, a.out, a.size, a.report, a.colours)
    finally:
        if server:
            server.terminate()
            server.wait()


if __name__ == "__main__":
    main()
