#!/usr/bin/python3
"""ctest study_localisation_band_measure: the band measures of band_statistics.py (and figures.py's
strain and strip) on a synthetic displacement field with a band of known direction, place and
width, so that a wrong measure fails.

Grain centres on a jittered triangular lattice of spacing d in a disc of radius 2.4 cm; the field
u = t g(s), s the distance across a band of direction ANGLE at AXIS from the centre, t the band's
direction, g' = GAMMA exp(-s^2 / (2 sigma^2)): a shear band whose shear strain profile is a
Gaussian of full width at half height FWHM_D d, off the centre. The measures must find the
direction to 1 degree (band_direction: the band measure's strip alone is 5 degrees off here), the axis to a bin, the thickness to a bin (d/2) plus the median's bias
(the half height is taken above the profile's median: 3 % narrower here), and a band measure well
above the same strain shuffled among the triangles.
"""
import math
import os
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import band_statistics as bs  # noqa: E402
import figures as fg  # noqa: E402

ANGLE, AXIS, FWHM_D, GAMMA, D = 35.0, 0.3, 8.0, 0.01, 0.14


class Synthetic:
    """What figures.accumulated_strain reads: run/fields/grains_000001.csv and the radii."""

    def __init__(self, path):
        self.run = path
        rng = np.random.default_rng(3)
        pts = [(i * D + (j % 2) * D / 2, j * D * math.sqrt(3) / 2) for i in range(-40, 41) for j in range(-40, 41)]
        p = np.array(pts) + rng.normal(0, 0.03 * D, (len(pts), 2))
        p = p[np.hypot(p[:, 0], p[:, 1]) < 2.4]
        th = math.radians(ANGLE)
        s = -p[:, 0] * math.sin(th) + p[:, 1] * math.cos(th) - AXIS
        sigma = FWHM_D * D / (2 * math.sqrt(2 * math.log(2)))
        g = GAMMA * sigma * math.sqrt(math.pi / 2) * np.array([math.erf(v / (sigma * math.sqrt(2))) for v in s])
        x, y = p[:, 0] + g * math.cos(th), p[:, 1] + g * math.sin(th)
        os.makedirs(os.path.join(path, "fields"))
        with open(os.path.join(path, "fields", "grains_000001.csv"), "w") as f:
            f.write("x0,y0,x,y\n")
            for row in zip(p[:, 0], p[:, 1], x, y):
                f.write(",".join(f"{v:.17g}" for v in row) + "\n")
        self.radii = np.full(len(p), D / 2)


def main():
    with tempfile.TemporaryDirectory() as tmp:
        case = Synthetic(tmp)
        tri, g, ok, area, _ = fg.accumulated_strain(case, 1, 1)
        share, ashare, ang, axis = fg.strip_share(tri, g, ok, area, offset=True, dang=bs.DANG)
        strip_ang = ang
        ang, axis = bs.band_direction(tri, g, ok, area, ang, axis)
        width = bs.band_thickness(tri, g, ok, area, ang, axis, D, radius=2.4)
        rng = np.random.default_rng(1)
        idx = np.nonzero(ok)[0]
        gs = g.copy()
        gs[idx] = g[rng.permutation(idx)]
        null = fg.strip_share(tri, gs, ok, area, dang=bs.DANG)[0]
        print(f"direction {ang:.1f} deg (band {ANGLE:g}; the band measure's strip {strip_ang:.0f}), axis {axis:.3f} cm ({AXIS:g}), thickness "
              f"{width / D:.2f} d ({FWHM_D:g}), band measure {share:.3f} (shuffled {null:.3f}, strip area share {ashare:.3f}), "
              f"99th percentile of the strain {np.percentile(g[ok], 99):.4f} ({GAMMA:g})")
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
        if errors:
            print("FAILED: " + ", ".join(errors))
            sys.exit(1)
        print("ok")


if __name__ == "__main__":
    main()
