#!/usr/bin/python3
"""ctest demo_paraview_render: the demo's hybrid run, reduced to 40 grains and 2 steps of the top, drawn
by ParaView off-screen (tools/paraview_render.py by pvpython, on an Xvfb of its own), then checked
against the run's own files, read here without ParaView (gembem's CSV and VTK readers):

  - ParaView read the grains of the last snapshot: as many as state_grains.csv has rows, at its
    centres with its radii (the snapshot is the final state's step), the contacts
    (state_contacts.csv's rows) and the boundary particles (host_particles.csv's); it drew each
    grain as a disc whose outer points lie at the grain's radius from its centre;
  - ParaView read the host field with host_field.vtu's points and cells, its in-plane von Mises
    stress finite and of the range computed here from sxx, syy, sxy, the colour bar over it;
  - the picture: a PNG of the asked size and many colours; inside every grain (0.6 r from its
    centre, away from lines and other discs) the discs' grey, just outside it (1.3 r) not; at
    the field's interior grid points, displaced by their displacement, the colour of their
    stress through matplotlib's viridis over that range. Pixels are placed by the parallel
    camera the script reports: a disc drawn at half or 1.5 times its radius, or off its centre,
    fails, and so does a host drawn at rest (its cavity moves by up to 0.29 cm, 20 pixels).

Skipped (exit 77) without pvpython, or without Xvfb and a display: tools/setup.sh
--with-paraview installs both.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "examples", "demo"))
sys.path.insert(0, os.path.join(ROOT, "python"))
import demo  # noqa: E402
from gembem.vtk import read_vtk  # noqa: E402

SKIP = 77
fails = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        fails.append(what)


def pvpython():
    """pvpython, or None with the reason to skip."""
    install = "install ParaView with `tools/setup.sh --with-paraview` (Debian packages paraview, xvfb, xauth)"
    pv = shutil.which("pvpython")
    if not pv:
        return None, f"pvpython not found on PATH: {install}"
    if not shutil.which("Xvfb") and not os.environ.get("DISPLAY"):
        return None, f"no display and no Xvfb (Debian's pvpython renders through X): {install}"
    return pv, None


def segment_distance(p, a, b):
    """Distances of point p to the segments a[k]-b[k]."""
    d = b - a
    t = np.clip(np.einsum("ij,ij->i", p - a, d) / np.maximum(np.einsum("ij,ij->i", d, d), 1e-300), 0, 1)
    return np.hypot(*(a + t[:, None] * d - p).T)


def main():
    pv, why = pvpython()
    if pv is None:
        print(f"SKIP demo_paraview_render: {why}")
        return SKIP
    out = tempfile.mkdtemp(prefix="gembem_paraview_")
    try:
        _, run, _ = demo.run_all(out, grains=40, steps=2, quiet=True)
        png, report = os.path.join(out, "picture.png"), os.path.join(out, "report.json")
        w, h = 1100, 800
        p = subprocess.run([pv, os.path.join(ROOT, "tools", "paraview_render.py"), run.path, png, "--size", str(w),
                            str(h), "--report", report], capture_output=True, text=True, timeout=120)
        log = p.stdout + p.stderr
        print(log.strip())
        check(p.returncode == 0 and "ERR|" not in log and "Traceback" not in log,
              f"pvpython ran without an error (exit {p.returncode})")
        if p.returncode != 0:
            return 1
        with open(report) as f:
            r = json.load(f)
        compare(run, r, png, w, h)
    finally:
        shutil.rmtree(out, ignore_errors=True)
    print(f"{len(fails)} failures")
    return 1 if fails else 0


def compare(run, r, png, w, h):
    g, c = run.state.grains, run.state.contacts
    xy, radius = np.column_stack([g["x"], g["y"]]), np.asarray(g["r"])
    n = len(radius)
    last = int(run.steps["step"][-1])
    check(r["step"] == r["host_step"] == last and r["grains"] == n,
          f"ParaView: {r['grains']} grains at step {r['step']:g}, the host at step {r['host_step']:g}; "
          f"state_grains.csv {n} at the last step {last}")
    if r["grains"] != n:
        return
    gap = max(np.abs(np.array(r["x"]) - xy[:, 0]).max(), np.abs(np.array(r["y"]) - xy[:, 1]).max(),
              np.abs(np.array(r["radius"]) - radius).max())
    check(gap <= 1e-12, f"ParaView's centres and radius array = state_grains.csv's to {gap:.2g}")
    ratio = np.array(r["glyph_radius"]) / radius
    check(np.all(np.abs(ratio - 1) < 1e-5), f"every disc's outer points at its radius: ratio {ratio.min():.7f} to "
          f"{ratio.max():.7f}")
    check(r["contacts"] == c.nrows, f"ParaView: {r['contacts']} contacts; state_contacts.csv {c.nrows}")
    bp = run.host_particles
    check(r["particles"] == bp.nrows, f"ParaView: {r['particles']} boundary particles; host_particles.csv {bp.nrows}")

    m = read_vtk(run.file("host_field.vtu"))
    sxx, syy, sxy = (m.point_data[k] for k in ("sxx", "syy", "sxy"))
    vm = np.sqrt(sxx * sxx - sxx * syy + syy * syy + 3 * sxy * sxy)
    check(r["field_points"] == len(m.points) and r["field_cells"] == len(m.offsets),
          f"ParaView: host field of {r['field_points']} points, {r['field_cells']} cells; host_field.vtu "
          f"{len(m.points)}, {len(m.offsets)}")
    lo, hi = vm.min(), vm.max()
    check(r["finite"] and np.allclose(r["von_mises_range"], [lo, hi], rtol=1e-9, atol=0)
          and np.allclose(r["color_range"], [lo, hi], rtol=1e-9, atol=0) and hi > 2 * lo > 0,
          f"von Mises stress finite, {r['von_mises_range'][0]:.6g} to {r['von_mises_range'][1]:.6g}, colour bar "
          f"{r['color_range'][0]:.6g} to {r['color_range'][1]:.6g}; from sxx, syy, sxy: {lo:.6g} to {hi:.6g}")

    import matplotlib
    import matplotlib.image
    img = matplotlib.image.imread(png)[:, :, :3]
    colours = len(np.unique((img * 255).astype(np.uint8).reshape(-1, 3), axis=0))
    check(img.shape[:2] == (h, w) and colours > 200, f"picture {img.shape[1]} x {img.shape[0]}, {colours} colours")
    ppu = h / (2 * r["parallel_scale"])  # pixels per unit length (parallel projection)
    fx, fy = r["focal_point"]

    def pixel(p):
        col, row = int(np.floor(w / 2 + (p[0] - fx) * ppu)), int(np.floor(h / 2 - (p[1] - fy) * ppu))
        return img[row, col] if 0 <= row < h and 0 <= col < w else None

    grey = np.array(r["grain_color"])
    # segments drawn in black: contacts (centre to centre or to the contact point) and the outline
    lines = read_vtk(run.file("host_boundary.vtp"))
    seg = [np.column_stack([c["xi"], c["yi"]]), np.column_stack([c["xj"], c["yj"]])]
    du = lines.cell_data["displacement"][:, :2]  # the outline is drawn displaced
    seg = [np.concatenate([seg[0], lines.points[0::2, :2] + du]), np.concatenate([seg[1], lines.points[1::2, :2] + du])]
    clear = r["tube_radius"] + 3 / ppu  # the thickest contact line's half width, and 3 pixels

    # discs drawn: the grains and the boundary particles (half-discs, taken whole), displaced
    disc_xy = np.concatenate([xy, np.column_stack([bp["x"] + bp["ux"], bp["y"] + bp["uy"]])])
    disc_r = np.concatenate([radius, bp["r"]])

    def alone(q, i):
        """q is 3 pixels or more away from every other disc and every line."""
        others = np.arange(len(disc_r)) != i
        return np.all(np.hypot(*(disc_xy[others] - q).T) > disc_r[others] + 3 / ppu) and \
            segment_distance(q, *seg).min() > clear

    inside = outside = 0
    bad_in, bad_out = [], []
    for i in range(n):
        for t in np.linspace(0, 2 * np.pi, 24, endpoint=False):
            u = np.array([np.cos(t), np.sin(t)])
            q = xy[i] + 0.6 * radius[i] * u
            if alone(q, i):
                inside += 1
                if np.abs(pixel(q) - grey).max() > 0.04:
                    bad_in.append(i)
            q = xy[i] + 1.3 * radius[i] * u
            if alone(q, i):
                outside += 1
                if np.abs(pixel(q) - grey).max() <= 0.04:
                    bad_out.append(i)
    check(inside >= 2 * n and not bad_in, f"the discs' grey at {inside} points 0.6 r inside the grains "
          f"({len(bad_in)} not, grains {sorted(set(bad_in))[:8]})")
    check(outside >= 2 * n and not bad_out, f"not the discs' grey at {outside} points 1.3 r outside the grains "
          f"({len(bad_out)} are, grains {sorted(set(bad_out))[:8]})")

    # The field's grid points inside its mesh (four quadrilaterals around them), displaced: the colour
    # map's colour.
    around = np.bincount(m.connectivity, minlength=len(m.points))
    inner = np.nonzero(around == 4)[0]
    at = m.points[:, :2] + m.point_data["displacement"][:, :2]
    expected = matplotlib.colormaps["viridis"]((vm[inner] - lo) / (hi - lo))[:, :3]
    drawn = np.array([pixel(at[k]) for k in inner])
    err = np.abs(drawn - expected).max(axis=1)
    check(len(inner) > 1000 and np.all(err < 0.05), f"the host's colour = viridis(von Mises) at {len(inner)} grid "
          f"points to {err.max():.3f} ({np.count_nonzero(err >= 0.05)} off by 0.05 or more)")


if __name__ == "__main__":
    sys.exit(main())
