#!/usr/bin/python3
"""ctest study_localisation_band_measure: the band measures of band_statistics.py (and figures.py's
strain and strip) on a synthetic displacement field with a band of known direction, place and
width, so that a wrong measure fails; in the cavity's disc and in the biaxial box's window
(box_bands.py).

Grain centres on a jittered triangular lattice of spacing d; the field u = t g(s), s the distance
across a band of direction ANGLE at AXIS from the centre, t the band's direction, g' = GAMMA
exp(-s^2 / (2 sigma^2)): a shear band whose shear strain profile is a Gaussian of full width at
half height FWHM_D d, off the centre. The measures must find the direction to 1 degree
(band_direction: the band measure's strip alone is 5 degrees off here), the axis to a bin, the
thickness to a bin (d/2) plus the median's bias (the half height is taken above the profile's
median: 3 % narrower here), and a band measure well above the same strain shuffled among the
triangles.

The cavity: the centres in a disc of radius 2.4 cm. The box: in a square of half side 2.4 cm, with
a second, stronger band (ten times the strain, FWHM 1 d) along the left wall, vertical, 1 d from
it: box_bands.py's window (MARGIN_D = 3 d inside the walls) must leave it out and find the inclined
band, and without the margin the wall's band must win (so the window is what leaves it out). The
grains turn by half the band's shear (the rigid rotation of simple shear) plus a noise a tenth of
the band's: the rotation ratio must be at least twice its null; box_bands.strain_windows must cut
a path whose e1 grows by 0.004 a step into windows of 3 steps (0.012 >= 0.01, counted by hand).
"""
import math
import os
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import band_statistics as bs  # noqa: E402
import box_bands  # noqa: E402
import figures as fg  # noqa: E402

ANGLE, AXIS, FWHM_D, GAMMA, D = 35.0, 0.3, 8.0, 0.01, 0.14
HALF = 2.4                        # the disc's radius, the square's half side [cm]
WALL_FWHM_D, WALL_GAMMA = 1.0, 10 * GAMMA


def shear_profile(s, fwhm, gamma):
    """The displacement along a band whose shear strain across it is gamma exp(-s^2 / (2 sigma^2))."""
    sigma = fwhm / (2 * math.sqrt(2 * math.log(2)))
    return gamma * sigma * math.sqrt(math.pi / 2) * np.array([math.erf(v / (sigma * math.sqrt(2))) for v in s])


def write_csv(path, columns):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(",".join(columns) + "\n")
        for row in zip(*columns.values()):
            f.write(",".join(v if isinstance(v, str) else f"{v:.17g}" for v in row) + "\n")


class Synthetic:
    """What figures.accumulated_strain reads: run/fields/grains_000001.csv and the radii; square:
    also the rest of a box run that box_bands.BoxRun reads (steps.csv, contacts/, grains.csv)."""

    def __init__(self, path, square=False):
        self.run = os.path.join(path, "run")
        rng = np.random.default_rng(3)
        pts = [(i * D + (j % 2) * D / 2, j * D * math.sqrt(3) / 2) for i in range(-40, 41) for j in range(-40, 41)]
        p = np.array(pts) + rng.normal(0, 0.03 * D, (len(pts), 2))
        p = p[np.max(np.abs(p), 1) < HALF] if square else p[np.hypot(p[:, 0], p[:, 1]) < HALF]
        th = math.radians(ANGLE)
        s = -p[:, 0] * math.sin(th) + p[:, 1] * math.cos(th) - AXIS
        g = shear_profile(s, FWHM_D * D, GAMMA)
        x, y = p[:, 0] + g * math.cos(th), p[:, 1] + g * math.sin(th)
        if square:   # the wall's band: the grains slide along y
            y = y + shear_profile(p[:, 0] - (-HALF + D), WALL_FWHM_D * D, WALL_GAMMA)
        write_csv(os.path.join(self.run, "fields", "grains_000001.csv"),
                  {"x0": p[:, 0], "y0": p[:, 1], "x": x, "y": y})
        self.radii = np.full(len(p), D / 2)
        if square:
            self.box_files(path, p, x, y, s, rng)

    def box_files(self, path, p, x, y, s, rng):
        n = len(p)
        sigma = FWHM_D * D / (2 * math.sqrt(2 * math.log(2)))
        rot = 0.5 * GAMMA * np.exp(-s**2 / (2 * sigma**2)) + rng.normal(0, 0.1 * GAMMA, n)
        write_csv(os.path.join(path, "grains.csv"), {"x": p[:, 0], "y": p[:, 1], "r": self.radii})
        for k, (gx, gy, gr) in enumerate([(p[:, 0], p[:, 1], np.zeros(n)), (x, y, rot)]):
            write_csv(os.path.join(self.run, "contacts", f"grains_{k:06d}.csv"),
                      {"x": gx, "y": gy, "r": self.radii, "rotation": gr})
        i, j = np.nonzero(np.triu(np.hypot(*(p[:, None, :] - p[None, :, :]).transpose(2, 0, 1)) < 1.2 * D, 1))
        write_csv(os.path.join(self.run, "contacts", "contacts_000001.csv"), {"i": i, "j": [str(v) for v in j]})
        with open(os.path.join(self.run, "run_info.yaml"), "w") as f:
            f.write("status: completed\n")
        side = 2 * HALF + D   # the walls touch the outermost grains
        write_csv(os.path.join(self.run, "steps.csv"),
                  {"step": [0, 1], "stage": [0, 3], "e1": [0, 0.01], "e2": [0, -0.01], "ev": [0, 0],
                   "width": [side, side], "height": [side, side], "stress_ratio": [0, 0.3], "seconds": [0, 0]})


def cavity(tmp):
    case = Synthetic(tmp)
    tri, g, ok, area, _ = fg.accumulated_strain(case, 1, 1)
    share, ashare, ang, axis = fg.strip_share(tri, g, ok, area, offset=True, dang=bs.DANG)
    strip_ang = ang
    ang, axis = bs.band_direction(tri, g, ok, area, ang, axis)
    width = bs.band_thickness(tri, g, ok, area, ang, axis, D, radius=HALF)
    rng = np.random.default_rng(1)
    idx = np.nonzero(ok)[0]
    gs = g.copy()
    gs[idx] = g[rng.permutation(idx)]
    null = fg.strip_share(tri, gs, ok, area, dang=bs.DANG)[0]
    print(f"cavity: direction {ang:.1f} deg (band {ANGLE:g}; the band measure's strip {strip_ang:.0f}), axis "
          f"{axis:.3f} cm ({AXIS:g}), thickness {width / D:.2f} d ({FWHM_D:g}), band measure {share:.3f} (shuffled "
          f"{null:.3f}, strip area share {ashare:.3f}), 99th percentile of the strain {np.percentile(g[ok], 99):.4f} "
          f"({GAMMA:g})")
    errors = []
    if abs(ang - ANGLE) > 1:   # (strip_ang: 30)
        errors.append("direction")
    if abs(axis - AXIS) > 0.05:
        errors.append("axis")
    if abs(width / D - 0.97 * FWHM_D) > 0.75:
        errors.append("thickness")
    if not share > 2 * null:
        errors.append("band measure against its null")
    if abs(np.percentile(g[ok], 99) - GAMMA) > 0.05 * GAMMA:   # (the max: a sliver on the hull)
        errors.append("strain")
    return ["cavity: " + e for e in errors]


def box(tmp):
    Synthetic(tmp, square=True)
    br = box_bands.BoxRun(tmp)
    m = box_bands.window_measures(br, 1, 1)
    margin = box_bands.MARGIN_D
    box_bands.MARGIN_D = 0
    try:
        wall = box_bands.window_measures(br, 1, 1)
    finally:
        box_bands.MARGIN_D = margin
    path = box_bands.strain_windows(0.004 * np.arange(11), 1, 10)
    print(f"box: direction {m['ang']:.1f} deg ({ANGLE:g}), axis {m['axis']:.3f} cm ({AXIS:g}), thickness "
          f"{m['thickness_d']:.2f} d ({FWHM_D:g}), band measure {m['band']:.3f} (shuffled {m['band_null']:.3f}), "
          f"rotation ratio {m['rot_ratio_med']:.2f} (null {m['rot_ratio_med_null']:.2f}); without the margin: "
          f"direction {wall['ang']:.1f} deg (the wall's band 90), band measure {wall['band']:.3f}; windows {path}")
    errors = []
    if abs(m["ang"] - ANGLE) > 1:
        errors.append("direction")
    if abs(m["axis"] - AXIS) > 0.05:
        errors.append("axis")
    if abs(m["thickness_d"] - 0.97 * FWHM_D) > 0.75:
        errors.append("thickness")
    if not m["band"] > 2 * m["band_null"]:
        errors.append("band measure against its null")
    if not m["rot_ratio_med"] > 2 * m["rot_ratio_med_null"]:
        errors.append("rotation ratio against its null")
    if abs(wall["ang"] - 90) > 1:
        errors.append("the wall's band without the margin")
    if path != [(1, 3), (4, 6), (7, 9)]:
        errors.append("windows")
    return ["box: " + e for e in errors]


def main():
    with tempfile.TemporaryDirectory() as t1, tempfile.TemporaryDirectory() as t2:
        errors = cavity(t1) + box(t2)
    if errors:
        print("FAILED: " + ", ".join(errors))
        sys.exit(1)
    print("ok")


if __name__ == "__main__":
    main()
