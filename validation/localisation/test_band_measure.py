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

The band network measure (band_statistics.network_measures: the profile contrast across 1 d
strips, its triangle-shuffled and block-shuffled nulls) at the study at scale's grain size (d =
0.044 cm, 10 800 centres in the disc) on a background of independent grain displacements (its
strain's median half the bands' peak): one band of 8 d at 35 deg, two conjugate bands of 8 d at 55
and 125 deg, a network of eight bands of 2 d (four at 40 deg, four at 140, 0.8 cm = 18 d apart),
and no band. Each band field must give at least band_statistics.BAND_BLOCK = 1.6 times the block
null (and twice the shuffled null) in each of its directions (to 3 degrees; the conjugate and the network: the
first and the second family); no band must stay below 1.2 times the block null and 1.4 times the
shuffled one. Measured (seeds 5-7): one band 3.1 x block, conjugate 2.3-2.4, network 2.2-2.5,
no band 1.01-1.04 (1.17-1.21 x shuffled: neighbouring triangles share corners, so even a field
without bands has strips more uneven than a shuffled one, which the block null keeps). 1.6 is the
criterion proposed for "a band forms" at 10 000 grains (the biaxial boxes' windows there: 1.6-2.3;
README, the control).

The followed host's cavity against its boundary particles' rest shapes (particle_mismatch): a
circle of 384 elements expanded, turned and stretched, each stretch and turn known analytically.
The rows of a runs table kept for runs measured elsewhere (--keep): read back, averaged by hand.
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
ND, NOISE = 0.044, 0.2            # network(): the study at scale's grain size (10 000 grains), the noise


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


class Field:
    """A disc of radius HALF filled with grain centres ND apart (a triangular lattice jittered by
    0.2 ND: no long straight rows), displaced by the shear bands `bands` ((direction, axis, FWHM
    in ND) each, peak shear strain GAMMA) plus an independent random displacement of sd NOISE
    GAMMA ND per grain and axis (its strain: median 0.5 GAMMA): what figures.accumulated_strain
    reads."""

    def __init__(self, path, bands, seed=5):
        self.run = os.path.join(path, "run")
        rng = np.random.default_rng(seed)
        n = int(HALF / ND) + 2
        p = np.array([(i * ND + (j % 2) * ND / 2, j * ND * math.sqrt(3) / 2)
                      for i in range(-n, n + 1) for j in range(-2 * n, 2 * n + 1)])
        p = p + rng.normal(0, 0.2 * ND, p.shape)
        p = p[np.hypot(p[:, 0], p[:, 1]) < HALF]
        u = rng.normal(0, NOISE * GAMMA * ND, p.shape)
        for ang, axis, fwhm_d in bands:
            th = math.radians(ang)
            s = -p[:, 0] * math.sin(th) + p[:, 1] * math.cos(th) - axis
            u += shear_profile(s, fwhm_d * ND, GAMMA)[:, None] * [math.cos(th), math.sin(th)]
        write_csv(os.path.join(self.run, "fields", "grains_000001.csv"),
                  {"x0": p[:, 0], "y0": p[:, 1], "x": p[:, 0] + u[:, 0], "y": p[:, 1] + u[:, 1]})
        self.radii = np.full(len(p), ND / 2)


def network(tmp):
    """band_statistics.network_measures (the profile contrast and its nulls) at the study at
    scale's grain size: one band, two conjugate bands, a network of thin bands, no band."""
    fields = [("one band", [(35.0, 0.3, 8.0)], (35.0,)),
              ("conjugate", [(55.0, 0.3, 8.0), (125.0, -0.4, 8.0)], (55.0, 125.0)),
              ("network", [(a, o, 2.0) for a in (40.0, 140.0) for o in (-1.2, -0.4, 0.4, 1.2)], (40.0, 140.0)),
              ("no band", [], ())]
    errors = []
    for name, bands, dirs in fields:
        case = Field(os.path.join(tmp, name), bands)
        tri, g, ok, area, _ = fg.accumulated_strain(case, 1, 1)
        m = bs.network_measures(tri, g, ok, area, ND)
        tri_r, block_r = m["contrast"] / m["contrast_null"], m["contrast"] / m["contrast_block"]
        print(f"{name}: profile contrast {m['contrast']:.3f} at {m['contrast_ang']:.0f} deg (next family "
              f"{m['contrast2']:.3f} at {m['contrast_ang2']:.0f}): {tri_r:.2f} x its shuffled null, {block_r:.2f} x its "
              f"block null; {fg.BAND_D:g} d strip share {m['share_d']:.3f}, {m['share_d'] / m['share_d_null']:.2f} x "
              f"its null at {m['share_d_ang']:.0f} deg")
        found = [m["contrast_ang"], m["contrast_ang2"]][:len(dirs)]
        if dirs and not (block_r >= bs.BAND_BLOCK and tri_r >= 2):
            errors.append(f"{name} against its nulls")
        if not dirs and not (block_r < 1.2 and tri_r < 1.4):
            errors.append("no band: not at its nulls")
        if any(min(bs.angle_apart(f, a) for f in found) > 3 for a in dirs):
            errors.append(f"{name}: directions")
        if len(dirs) == 2 and not m["contrast2"] / m["contrast_block"] >= bs.BAND_BLOCK:
            errors.append(f"{name}: the second family against the block null")
    # persistent_band on windows counted by hand: ratios 1.7 (>= 1.6) but the fourth; directions
    # 130, 52 (130's mirror 50: the same family), 60 (8 from 52), -, 40, 90 (50 from 40 and 140):
    # runs of 3, then 1 and 1
    wins = [{"contrast": 1.7 if r else 1.0, "contrast_block": 1.0, "contrast_ang": a}
            for r, a in ((1, 130), (1, 52), (1, 60), (0, 0), (1, 40), (1, 90))]
    if bs.persistent_band(wins) != 3:
        errors.append(f"persistent_band: {bs.persistent_band(wins)} windows (3)")
    return ["network: " + e for e in errors]


def particles(tmp):
    """band_statistics.particle_mismatch (a followed cavity against its boundary particles' rest
    shapes) on a circle of 384 elements, numbered from 64 and listed out of order as a run may:
    a uniform expansion by 10 % (stretch 0.1, no turn), a rigid turn by 5 deg about the centre
    (no stretch, a turn of 5 deg) and a stretch of x by 1.2 (the chord where it runs along x:
    stretch 0.2 to the chord's discretisation, 2 pi / 384; a chord at phi turns to atan(tan phi /
    1.2), most where tan phi = sqrt(1.2): atan(sqrt(1.2)) - atan(1 / sqrt(1.2)) = 5.216 deg)."""
    m, r = 384, 2.5
    th = 2 * math.pi * (np.arange(m) + 0.5) / m
    x, y = r * np.cos(th), r * np.sin(th)
    t5 = math.radians(5.0)
    cases = [("expansion", 0.1 * x, 0.1 * y, 0.1, 0.0),
             ("turn", x * math.cos(t5) - y * math.sin(t5) - x, x * math.sin(t5) + y * math.cos(t5) - y, 0.0, 5.0),
             ("stretch x", 0.2 * x, 0 * y, 0.2, math.degrees(math.atan(math.sqrt(1.2)) - math.atan(1 / math.sqrt(1.2))))]
    order = np.roll(np.arange(m), 100)
    errors = []
    for name, ux, uy, stretch, turn in cases:
        d = os.path.join(tmp, name.replace(" ", "_"))
        write_csv(os.path.join(d, "host_particles.csv"),
                  {"element": [str(64 + i) for i in order], "x": x[order], "y": y[order], "ux": ux[order], "uy": uy[order]})
        got = bs.particle_mismatch(d)
        print(f"particles, {name}: stretch {got[0]:.5f} ({stretch}), turn {got[1]:.4f} deg ({turn:.4f})")
        if abs(got[0] - stretch) > 1e-3 or abs(got[1] - turn) > 0.02:
            errors.append(f"particles: {name}")
    return errors


def kept(tmp):
    """band_statistics.py --keep: the rows of a runs table read back (an empty cell left out) and
    their table row: band measures 0.3 and 0.5 give 0.40 +- 0.14 (2) (sd sqrt(0.02) = 0.1414),
    a thickness given by one run only 3.0 (1); a run measured again against its row: 10 % apart."""
    with open(os.path.join(tmp, "statistics_runs.csv"), "w") as f:
        f.write("case,band,thickness_d\ng/s01,0.3,3\ng/s02,0.5,\n")
    here = bs.HERE
    bs.HERE = tmp
    rows = bs.kept_rows()
    bs.HERE = here
    by = {"g": list(rows.values())}
    got = (bs.mean_row(by, ["g"], "band", "b", "{:.2f}"), bs.mean_row(by, ["g"], "thickness_d", "t", "{:.1f}"),
           bs.differs({"band": 0.33, "thickness_d": 3.0}, rows["g/s01"]))
    print(f"kept rows: {got[0]} {got[1]}, again: {got[2][0]:.3f} ({got[2][1]})")
    ok = (got[0] == "| b | 0.40 +- 0.14 (2) |" and got[1] == "| t | 3.0 (1) |" and "thickness_d" not in rows["g/s02"]
          and abs(got[2][0] - 0.1) < 1e-9 and got[2][1] == "band")
    return [] if ok else ["kept rows"]


def main():
    with tempfile.TemporaryDirectory() as t1, tempfile.TemporaryDirectory() as t2, tempfile.TemporaryDirectory() as t3:
        errors = cavity(t1) + box(t2) + network(t3) + particles(t1) + kept(t3)
    if errors:
        print("FAILED: " + ", ".join(errors))
        sys.exit(1)
    print("ok")


if __name__ == "__main__":
    main()
