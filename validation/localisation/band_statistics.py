#!/usr/bin/python3
"""The localisation study's statistics: per run the band's measures, per case their
mean, standard deviation and count (statistics.md), and the figures statistics_*.png.

Every run (study.py stat_cases: 8 cases x 20 packings, 1000 grains) is read only up to its last
step within the host's small-strain range: the host's largest principal strain magnitude on the
cavity wall (wall_strain) <= study.STAT_HOST_STRAIN; with --ring, on the ring at 1.5 R instead
(ring_strain; a sensitivity run, 2.2-4 times the travel: statistics_ring*). On those steps, per run:

  window    the strain accumulated over WINDOW steps (0.05 cm of the top's travel), ending at each
            step from the first full window to the last allowed step (a run allowed fewer steps,
            at least 2: one window of them all);
  band      the window with the largest band measure (figures.strip_share: the largest share of
            sum(gamma area) in a straight strip 0.5 cm wide, here in 1 degree steps), the window's
            end the band's time; the band's direction and axis: band_direction's refinement of
            the strip's;
  phi       mobilised friction angle at the band's time: sin phi = (s1 - s3) / (s1 + s3) of the
            zone's Love-Weber stress (zone_stress: sum over the grains of branch x force);
  psi       dilatancy angle over the band's window: sin psi = (de1 + de2) / (de1 - de2) of the
            zone's strain increment (the affine fit of the grains' displacements; tension positive,
            psi > 0 dilation);
  theta     the angle between the band's axis and the minor principal stress direction (0-90 deg),
            against theta_MC = 45 + phi/2, theta_R = 45 + psi/2, theta_A = 45 + (phi + psi)/4;
  thickness the full width at half height (above the profile's median) of the mean shear strain
            across the band (bins of half a mean diameter), in mean grain diameters d;
  null      the band measure of the band's window with its triangles' (strain, area) pairs
            shuffled among their places (a field with the same values and no band);
  rotation  mean (and median) |rotation| over the window of the grains within the band
            (|distance to the axis| <= max(thickness/2, d)) over that of the others, rattlers
            (< 2 contacts at the window's end) and grains turning more than SPIN (a mechanism)
            left out; its null: the same for random strips as wide;
  onset     the first window in which the band's strip holds at least half way from its area
            share to its share at the band's time; where along the strip that window's strain
            peaks (bins of d, 3-bin mean): its distance from the cavity wall in d;
  host      the host's shear strain increment over the band's window where the band's axis
            meets the cavity (the two wall elements, and the two ring points at 1.5 R, nearest
            each end) over that at the mirror points (x -> -x: the loading is symmetric about
            the vertical axis, so the mirror points see the same loading without the band).
  network   the band network measures (network_measures; README, the control) on the windows
            that follow each other without overlap and on the whole allowed travel: the profile
            contrast (the strain's mean in strips 1 d wide across each direction: std / mean,
            the largest over the directions) over its block null (the same with the window's
            cells 4 d wide shuffled and turned) and its shuffled null, its direction families;
            "a band forms": at least BAND_BLOCK x the block null in two windows in a row, in one
            direction (or its mirror image about the vertical) to 15 deg (persistent_band); and the
            share of the strain in the best strip 8 d wide over its shuffled null.

With --scale, the study at scale (study.py scale_cases: 1e4 grains, the host following its
deformed boundary) over each run's whole travel, no host strain bound: scale.md, scale_runs.csv,
scale_maps.png, scale_measures.png.

With --keep, a run not completed in RUNS_DIR keeps its row of the last <out>_runs.csv (a study
run in parts, on several machines): the runs found are measured (a run found and kept is measured
again, and the largest relative difference to its kept row printed), the table and the measures'
figure take every row, and the maps need the directory of each case's median run (named if it is
missing).

Usage: validation/localisation/band_statistics.py [RUNS_DIR] [--ring | --scale] [--keep]   (default runs/localisation)
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PatchCollection  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
import gembem  # noqa: E402
from gembem.yamlfile import read_yaml  # noqa: E402
import study  # noqa: E402
import figures as fg  # noqa: E402  (the strain on the triangles, the band measure: written once, there)

ARGS = [a for a in sys.argv[1:] if not a.startswith("--")]
RUNS = ARGS[0] if ARGS else os.path.join(HERE, "..", "..", "runs", "localisation")
# Where the host's strain is bounded: on the cavity wall (its largest), or with --ring on the
# ring at 1.5 R (the sensitivity run: outputs statistics_ring*)
BOUND_AT = "ring" if "--ring" in sys.argv else "wall"
SCALE = "--scale" in sys.argv   # the study at scale: the whole travel, no bound
KEEP = "--keep" in sys.argv     # rows of the last <out>_runs.csv stand for runs not found
OUT = "scale" if SCALE else "statistics" + ("_ring" if BOUND_AT == "ring" else "")
# the runs (name, kn_g, P, rolling, seed), the cases (group, kn_g, P, rolling), packings per case
CASES = study.scale_cases() if SCALE else study.stat_cases()
GROUPS = ([("scale/" + g, k, p, r) for g, k, p, r in study.stat_groups() if p in study.SCALE_P] if SCALE
          else study.stat_groups())
SEEDS = study.SCALE_SEEDS if SCALE else study.STAT_SEEDS
CAVITY = study.SCALE_CAVITY if SCALE else study.STAT_CAVITY
WINDOW = 5          # steps of 0.01 cm: the window over which the band's strain accumulates
DANG = 1            # degrees between the band measure's strip directions
SPIN = 1.0          # radians over a window: a grain turning more is in a mechanism (README)
NULL_SHUFFLES, NULL_SEED = 5, 20  # the nulls' shuffles (and 4x as many random strips), their seed
BLOCK_D = 4         # mean diameters: the cells of the profile contrast's block null (network_measures)
BAND_BLOCK = 1.6    # profile contrast / its block null that counts as a band or a band network (README)
EPISODE = fg.EPISODE  # band measure that counts as a band (0.45, as the extended cases)
R_USABLE = 2.5 * (math.cos(math.pi / CAVITY) - math.sin(math.pi / CAVITY))


def principal(exx, eyy, exy):
    """Principal values (larger first) and the direction (radians from +x) of the larger."""
    c, r = 0.5 * (exx + eyy), np.hypot(0.5 * (exx - eyy), exy)
    return c + r, c - r, 0.5 * np.arctan2(2 * exy, exx - eyy)


def ring_strain(run, k):
    """The host ring's largest principal strain magnitude at step k (total strain, tension +)."""
    h = run.field("host_ring", k)
    e1, e2, _ = principal(h["exx"], h["eyy"], h["exy"])
    return float(np.max(np.maximum(np.abs(e1), np.abs(e2))))


def wall_strain(run, k):
    """The host's largest principal strain magnitude on the cavity wall at step k: plane strain
    Hooke on each element's hoop and normal stress (fields/host_wall; no shear: the boundary
    contacts are frictionless), eps = (s - nu (s_t + s_n)) / (2 G)."""
    h = run.field("host_wall", k)
    tr = h["hoop"] + h["normal"]
    et, en = (h["hoop"] - study.NU * tr) / (2 * study.G), (h["normal"] - study.NU * tr) / (2 * study.G)
    return float(np.max(np.maximum(np.abs(et), np.abs(en))))


def zone_stress(run, k):
    """The zone's Love-Weber stress at the end of step k (tension +; per unit area of the usable
    disc, which cancels in phi): sum over contacts of branch (i to j, or i to the contact point on
    a boundary particle) x force on i. Force on i: -pn n - pt t, t = (-ny, nx) (the sign that
    balances every grain: checked on a run, residual 2e-4 of the mean pn against 4 with +pt)."""
    c = run.contacts(k)
    n = np.stack([c["nx"], c["ny"]], 1)
    t = np.stack([-c["ny"], c["nx"]], 1)
    f = -c["pn"][:, None] * n - c["pt"][:, None] * t
    lvec = np.stack([c["xj"] - c["xi"], c["yj"] - c["yi"]], 1)
    s = (lvec[:, :, None] * f[:, None, :]).sum(0) / (math.pi * R_USABLE**2)
    return 0.5 * (s + s.T)  # the symmetric part (rolling moments make it slightly asymmetric)


def zone_strain(run, k0, k1):
    """The zone's strain increment from the start of step k0 to the end of k1: the symmetric part
    of the displacement gradient of the best affine fit of the grains' displacements."""
    a, b = run.field("grains", k0), run.field("grains", k1)
    X = np.stack([np.ones_like(a["x0"]), a["x0"], a["y0"]], 1)
    gx = np.linalg.lstsq(X, b["x"] - a["x0"], rcond=None)[0]
    gy = np.linalg.lstsq(X, b["y"] - a["y0"], rcond=None)[0]
    H = np.array([[gx[1], gx[2]], [gy[1], gy[2]]])
    return 0.5 * (H + H.T)


class StatRun:
    """One run of the statistics, in the form figures.accumulated_strain reads (run, radii)."""

    def __init__(self, name):
        self.name = name
        self.dir = os.path.join(RUNS, name) if SCALE else os.path.join(RUNS, "statistics", name)
        self.run = os.path.join(self.dir, "run")
        self.r = gembem.Run(self.run)
        self.radii = fg.read_csv(os.path.join(self.dir, "grains.csv"))["r"]
        self.d = 2 * self.radii.mean()
        self.first_top = study.STEPS_P + 2
        self.P = next(c for c in CASES if c[0] == name)[2]
        hs = self.r.host_steps
        top = hs["group"] == "top"
        self.travel = -hs["uy"][top]
        steps = self.r.steps_of("fields", "host_ring")
        self.ring = {k: ring_strain(self.r, k) for k in steps}
        self.wall = {k: wall_strain(self.r, k) for k in steps}
        bound = self.wall if BOUND_AT == "wall" else self.ring
        ok = [k for k in steps if k >= self.first_top and (SCALE or bound[k] <= study.STAT_HOST_STRAIN)]
        self.last = max(ok) if ok else self.first_top - 1  # the last step within the allowed strain


def particle_mismatch(run_dir):
    """How far a followed host's cavity moved from its boundary particles' shapes, which keep their
    size and normal at rest (docs/hybrid.md, "A host that follows its boundary"): at the run's end
    (host_particles.csv: rest centres, summed displacements), the chord between neighbouring
    elements' centres against its rest length and direction, over the cavity's closed loop (the
    chord is about an element's length, the particles' diameter). Returns the largest stretch
    |L/L0 - 1|, the largest turn [deg] and the largest change of length |L - L0|."""
    p = fg.read_csv(os.path.join(run_dir, "host_particles.csv"))
    o = np.argsort(p["element"])
    x0, y0 = p["x"][o], p["y"][o]
    x1, y1 = x0 + p["ux"][o], y0 + p["uy"][o]
    c0 = np.stack([np.roll(x0, -1) - x0, np.roll(y0, -1) - y0], 1)
    c1 = np.stack([np.roll(x1, -1) - x1, np.roll(y1, -1) - y1], 1)
    l0, l1 = np.hypot(*c0.T), np.hypot(*c1.T)
    if l0.max() > 1.5 * l0.min():
        raise SystemExit(f"{run_dir}: the cavity's elements are not in loop order by number")
    turn = np.degrees(np.arctan2(c0[:, 0] * c1[:, 1] - c0[:, 1] * c1[:, 0], (c0 * c1).sum(1)))
    return float(np.abs(l1 / l0 - 1).max()), float(np.abs(turn).max()), float(np.abs(l1 - l0).max())


def profile(coord, w, v, edges):
    """The w-weighted mean of v in the bins of coord."""
    num, _ = np.histogram(coord, edges, weights=w * v)
    den, _ = np.histogram(coord, edges, weights=w)
    return np.where(den > 0, num / np.maximum(den, 1e-300), np.nan), den


def fwhm(s, prof, axis, half_strip):
    """Width of the profile's peak near `axis` at half its height above the median (contiguous
    bins), and the peak bin."""
    ds = s[1] - s[0]
    p = np.convolve(np.nan_to_num(prof), np.ones(3) / 3, "same")
    base = np.nanmedian(prof)
    near = np.nonzero(np.abs(s - axis) <= half_strip)[0]
    j = near[np.argmax(p[near])]
    half = base + 0.5 * (p[j] - base)
    lo = j
    while lo > 0 and p[lo - 1] >= half:
        lo -= 1
    hi = j
    while hi < len(p) - 1 and p[hi + 1] >= half:
        hi += 1
    return (hi - lo + 1) * ds, j


def band_frame(tri, ang):
    """Triangle centroids' coordinates across (s, as figures.strip_share) and along (t) a
    direction ang (deg from +x)."""
    t = tri.triangles
    cx, cy = tri.x[t].mean(1), tri.y[t].mean(1)
    th = math.radians(ang)
    return -cx * math.sin(th) + cy * math.cos(th), cx * math.cos(th) + cy * math.sin(th)


def band_direction(tri, g, ok, area, ang0, axis0, span=10.0, dstep=0.5):
    """The band's direction and axis refined near the band measure's strip (ang0 +- span degrees,
    axis0 +- STRIP): those of the strip STRIP wide with the largest area-weighted MEAN shear
    strain. The band measure's strip maximises the strain's SUM, which favours long chords: a band
    wider than the strip and off the centre comes out a few degrees towards the centre (5 degrees
    on the ctest's band)."""
    w, wg = np.where(ok, area, 0), np.where(ok, g * area, 0)
    best = (-1.0, ang0, axis0)
    for ang in np.arange(ang0 - span, ang0 + span + 1e-9, dstep):
        sc, _ = band_frame(tri, ang)
        for off in np.arange(axis0 - fg.STRIP, axis0 + fg.STRIP + 1e-9, 0.01):
            m = np.abs(sc - off) <= fg.STRIP / 2
            if w[m].sum() > 0 and wg[m].sum() / w[m].sum() > best[0]:
                # a direction beyond [0, 180) is the same line with its normal reversed
                best = (wg[m].sum() / w[m].sum(), ang % 180, off if 0 <= ang < 180 else -off)
    return best[1], best[2]


def band_thickness(tri, g, ok, area, ang, axis, d, radius=R_USABLE):
    """The band's thickness [length]: the full width at half height (above the median) of the
    area-weighted mean shear strain across the direction ang, in bins of d/2, around the strip's
    axis (ctest study_localisation_band_measure checks it on a band of known width)."""
    sc, _ = band_frame(tri, ang)
    edges = np.arange(-radius, radius + d / 2, d / 2)
    prof, _ = profile(sc, np.where(ok, area, 0), np.where(ok, g, 0), edges)
    width, _ = fwhm(0.5 * (edges[1:] + edges[:-1]), prof, axis, fg.STRIP / 2)
    return width


def shuffled(g, ok, area, rng):
    """NULL_SHUFFLES copies of a window's (strain, area) with the pairs of its triangles (ok)
    shuffled among their places: the same values without spatial order, the band measures' null.
    Strain and area together: a sliver's huge strain stays on a sliver's area."""
    idx = np.nonzero(ok)[0]
    for _ in range(NULL_SHUFFLES):
        gs, as_ = g.copy(), area.copy()
        perm = rng.permutation(idx)
        gs[idx], as_[idx] = g[perm], area[perm]
        yield gs, as_


def block_shuffled(cx, cy, wa, size, rng):
    """The points (cx, cy) (areas wa) with the square cells `size` wide that they fill (at least
    90 % of the cell's area: the window's ragged edge stays in place) moved among each other and
    turned by a random multiple of 90 deg: the strain's order within a cell kept, beyond it gone."""
    i, j = np.floor(cx / size).astype(int), np.floor(cy / size).astype(int)
    cells, inv = np.unique(np.stack([i, j], 1), axis=0, return_inverse=True)
    inv = inv.ravel()
    full = np.nonzero(np.bincount(inv, wa) >= 0.9 * size**2)[0]
    dest, turn = np.arange(len(cells)), np.zeros(len(cells), int)
    dest[full], turn[full] = full[rng.permutation(len(full))], rng.integers(0, 4, len(full))
    centre = (cells + 0.5) * size
    lx, ly = cx - centre[inv, 0], cy - centre[inv, 1]
    q = turn[inv]
    for k in (1, 2, 3):   # turned by k quarter turns: (x, y) -> (-y, x), k times
        m = q >= k
        lx[m], ly[m] = -ly[m], lx[m].copy()
    return centre[dest[inv], 0] + lx, centre[dest[inv], 1] + ly


def network_measures(tri, g, ok, area, d):
    """The band measures that see a band network as well as one band, on a window's strain (tri,
    g, ok, area: figures.accumulated_strain's, ok limited to the measuring window), d the mean
    grain diameter, as a dict:
      contrast       figures.profile_contrast in strips PROFILE_D d wide, its largest over the
                     directions (DANG steps), its direction contrast_ang; contrast_ang2 and
                     contrast2: the largest at least 30 deg from it (a conjugate family);
      contrast_null  the same of the window's (strain, area) shuffled among its triangles (the
                     mean of NULL_SHUFFLES shuffles, as band_null): a field without any order;
      contrast_block the same with the window's cells BLOCK_D d wide shuffled and turned
                     (block_shuffled; the mean of NULL_SHUFFLES): a field with the strain's order
                     over a few grains (the triangles' shared corners, force chains) and none
                     beyond, so contrast / contrast_block measures the order along bands alone;
      share_d        figures.strip_share in a strip BAND_D d wide (steps of d/2), its area share
                     share_d_area, its direction share_d_ang, and its shuffled null share_d_null."""
    w = fg.PROFILE_D * d
    c, ang, per = fg.profile_contrast(tri, g, ok, area, w, dang=DANG)
    ang2, c2 = fg.second_direction(per, dang=DANG)
    share, ashare, sang = fg.strip_share(tri, g, ok, area, width=fg.BAND_D * d, step=d / 2, dang=DANG)
    rng = np.random.default_rng(NULL_SEED)
    cn, sn = [], []
    for gs, as_ in shuffled(g, ok, area, rng):
        cn.append(fg.profile_contrast(tri, gs, ok, as_, w, dang=DANG)[0])
        sn.append(fg.strip_share(tri, gs, ok, as_, width=fg.BAND_D * d, step=d / 2, dang=DANG)[0])
    t = tri.triangles
    cx, cy, wg, wa = tri.x[t].mean(1)[ok], tri.y[t].mean(1)[ok], (g * area)[ok], area[ok]
    cb = [fg.contrast_per_direction(*block_shuffled(cx, cy, wa, BLOCK_D * d, rng), wg, wa, w, DANG).max()
          for _ in range(NULL_SHUFFLES)]
    return dict(contrast=c, contrast_ang=ang, contrast_ang2=ang2, contrast2=c2, contrast_null=float(np.mean(cn)),
                contrast_block=float(np.mean(cb)), share_d=share, share_d_area=ashare, share_d_ang=sang,
                share_d_null=float(np.mean(sn)))


def strip_measures(sr, k0, k1, tri, g, ok, area, ang, axis, radius=R_USABLE, among=None):
    """The measures of a window's band measure strip (direction ang, axis: figures.strip_share's)
    over the window of steps k0-k1 (its strain tri, g, ok, area: figures.accumulated_strain's, ok
    limited to the measuring window), as a dict: the refined direction and axis (ang, axis), the
    null (band_null), the thickness (width [length], thickness_d), the rotation ratios and their
    nulls (rot_ratio*), spinning and rattlers.
    radius: the window's largest distance from the centre (the thickness' profile spans +-radius,
    the rotations' random strips lie within radius/2 of it); among: the grains (bool per grain)
    whose rotations count, default all."""
    out = {}
    ang, axis = band_direction(tri, g, ok, area, ang, axis)
    out.update(ang=ang, axis=axis)
    # the null: the same window's strain values shuffled among its triangles (no spatial order;
    # NULL_SHUFFLES seeded shuffles, their mean): what the band measure gives without a band
    rng = np.random.default_rng(NULL_SEED)
    out["band_null"] = float(np.mean([fg.strip_share(tri, gs, ok, as_, dang=DANG)[0]
                                      for gs, as_ in shuffled(g, ok, area, rng)]))
    width = band_thickness(tri, g, ok, area, ang, axis, sr.d, radius)
    out["width"], out["thickness_d"] = width, width / sr.d
    # rotations of the grains in and out of the band over the window
    ga, gb = sr.r.grains(k0 - 1), sr.r.grains(k1)
    th = math.radians(ang)
    dist = np.abs(-gb["x"] * math.sin(th) + gb["y"] * math.cos(th) - axis)
    rot = np.abs(gb["rotation"] - ga["rotation"])
    # rattlers (fewer than 2 contacts at the window's end) spin freely: left out of both means
    c = sr.r.contacts(k1)
    jj = np.array([int(j) for j in c["j"] if str(j).isdigit()], int)  # j: a grain, a wall or p<k> a particle
    z = np.bincount(c["i"].astype(int), minlength=len(rot)) + np.bincount(jj, minlength=len(rot))
    # grains spinning in a mechanism (both contacts sliding: the rotation is undetermined, the
    # solver's value arbitrary; 7326 rad in one step on k0.01_p100_nr/s11) are left out too
    spin = rot > SPIN
    out["spinning"] = int((spin & (z >= 2)).sum())
    held = (z >= 2) & ~spin & (True if among is None else among)
    out["rattlers"] = int((z < 2).sum())
    inside = (dist <= max(width / 2, sr.d)) & held
    outside = (~inside) & held
    # means (the brief's measure) and medians: a few grains spinning between two contacts swing
    # the means' ratio (0.01 and 13 on one run), not the medians'
    few = inside.sum() < 5
    out["rot_ratio"] = np.nan if few else float(rot[inside].mean() / rot[outside].mean())
    out["rot_ratio_med"] = np.nan if few else float(np.median(rot[inside]) / np.median(rot[outside]))
    # its null: the same ratio for strips as wide at random directions and offsets (|offset| < radius/2)
    rr = []
    for _ in range(NULL_SHUFFLES * 4):
        a2, o2 = math.radians(rng.uniform(0, 180)), rng.uniform(-radius / 2, radius / 2)
        ins = np.abs(-gb["x"] * math.sin(a2) + gb["y"] * math.cos(a2) - o2) <= max(width / 2, sr.d)
        if (ins & held).sum() >= 5:
            rr.append((rot[ins & held].mean() / rot[~ins & held].mean(),
                       np.median(rot[ins & held]) / np.median(rot[~ins & held])))
    out["rot_ratio_null"], out["rot_ratio_med_null"] = (float(v) for v in np.mean(rr, 0))
    return out


def angle_apart(a, b):
    """The angle between two directions [deg] (modulo 180: 0-90)."""
    x = abs(a - b) % 180
    return min(x, 180 - x)


def persistent_band(net, within=15.0):
    """The longest run of successive windows (network_measures' dicts, in order) whose profile
    contrast reaches BAND_BLOCK x its block null, each window's direction within `within` degrees
    of the last's or of its mirror image about the vertical (the loading's axis: a conjugate
    network's best family may swap from window to window): bands that stay, not streaks that move.
    2 or more: "a band forms"."""
    longest = run = 0
    for i, m in enumerate(net):
        if m["contrast"] < BAND_BLOCK * m["contrast_block"]:
            run = 0
        else:
            a, b = m["contrast_ang"], net[i - 1]["contrast_ang"] if i else None
            same = run > 0 and min(angle_apart(a, b), angle_apart(a, 180 - b)) <= within
            run = run + 1 if same else 1
        longest = max(longest, run)
    return longest


def network_run(sr, wins, whole):
    """The band network measures of a run (network_measures) on its windows that follow each
    other without overlap (wins: measure's window tuples) and on the whole allowed loading (whole:
    its tri, g, ok, area), as a dict (NET_KEYS): those of the window with the largest profile
    contrast over its block null, how many windows reach BAND_BLOCK, the longest run of them in
    one direction (persistent_band)."""
    net = [network_measures(tri, g, ok, area, sr.d) for _, _, _, _, _, _, tri, g, ok, area in wins]
    ratio = [m["contrast"] / m["contrast_block"] for m in net]
    q = int(np.argmax(ratio))
    m = net[q]
    longest = persistent_band(net)
    mw = network_measures(*whole, sr.d)
    return dict(net_ratio=ratio[q], net_ratio_shuffled=m["contrast"] / m["contrast_null"], net_contrast=m["contrast"],
                net_ang=m["contrast_ang"], net_ang2=m["contrast_ang2"], net_ratio2=m["contrast2"] / m["contrast_block"],
                net_travel=float(sr.travel[wins[q][1]]), net_windows=len(net),
                net_band_windows=sum(r >= BAND_BLOCK for r in ratio), net_longest=longest,
                net_whole_ratio=mw["contrast"] / mw["contrast_block"],
                share_d_ratio=max(n["share_d"] / n["share_d_null"] for n in net),
                share_d_whole_ratio=mw["share_d"] / mw["share_d_null"])


def measure(sr):
    """The measures of one run (a dict; None where the allowed steps hold no full window)."""
    out = {"case": sr.name, "travel": float(sr.travel[sr.last]), "last": sr.last, "d": sr.d}
    # the grains' own confinement: the zone's mean pressure (Love-Weber) at the end of the
    # host's confinement, over P (the packing's pre-stress and the host's shielding set it, not P)
    s0 = zone_stress(sr.r, sr.first_top - 1)
    out["p_zone_P"] = float(-0.5 * (s0[0, 0] + s0[1, 1]) / sr.P)
    if sr.last >= sr.first_top:   # how far the zone went: its strain over the allowed loading
        ez = zone_strain(sr.r, sr.first_top, sr.last)
        out["zone_axial"], out["zone_vol"] = -ez[1, 1], ez[0, 0] + ez[1, 1]
    # windows of WINDOW steps; a run allowed fewer (but at least 2) loading steps: one window of them all
    win = min(WINDOW, sr.last - sr.first_top + 1)
    out["window"] = win
    if win < 2:
        return out
    ends = list(range(sr.first_top + win - 1, sr.last + 1))
    wins = []
    for k1 in ends:
        k0 = k1 - win + 1
        tri, g, ok, area, _ = fg.accumulated_strain(sr, k0, k1)
        share, ashare, ang, axis = fg.strip_share(tri, g, ok, area, offset=True, dang=DANG)
        wins.append((k0, k1, share, ashare, ang, axis, tri, g, ok, area))
    q = int(np.argmax([w[2] for w in wins]))
    k0, k1, share, ashare, ang, axis, tri, g, ok, area = wins[q]
    out.update(band=share, band_area=ashare, band_end=k1, band_travel=float(sr.travel[k1]), strip_ang=ang)
    sm = strip_measures(sr, k0, k1, tri, g, ok, area, ang, axis)
    ang, axis = sm["ang"], sm["axis"]
    del sm["width"]
    out.update(sm)
    out["axis_r"] = abs(axis) / R_USABLE
    # the whole allowed loading's band measure
    tri_a, g_a, ok_a, area_a, _ = fg.accumulated_strain(sr, sr.first_top, sr.last)
    out["band_whole"] = fg.strip_share(tri_a, g_a, ok_a, area_a, dang=DANG)[0]
    out.update(network_run(sr, wins[::win], (tri_a, g_a, ok_a, area_a)))
    # stress, dilatancy, orientation
    s = zone_stress(sr.r, k1)
    s1, s3, dir1 = principal(s[0, 0], s[1, 1], s[0, 1])   # s1 >= s3 (tension +): s3 most compressive
    out["phi"] = math.degrees(math.asin((s1 - s3) / -(s1 + s3)))
    e = zone_strain(sr.r, k0, k1)
    e1, e2, _ = principal(e[0, 0], e[1, 1], e[0, 1])
    out["psi"] = math.degrees(math.asin(np.clip((e1 + e2) / (e1 - e2), -1, 1)))
    minor = math.degrees(dir1) % 180   # the least compressive principal stress (sigma_3 in soil terms)
    dth = abs(ang - minor) % 180
    out["theta"] = min(dth, 180 - dth)
    out["minor_dir"] = minor
    out["theta_mc"] = 45 + out["phi"] / 2
    out["theta_r"] = 45 + out["psi"] / 2
    out["theta_a"] = 45 + (out["phi"] + out["psi"]) / 4
    gb = sr.r.grains(k1)
    th = math.radians(ang)
    # onset: the first window whose strain in the band's strip is half way to its band-time share
    target = ashare + 0.5 * (share - ashare)
    for k0o, k1o, _, _, _, _, trio, go, oko, areao in wins:
        so, to = band_frame(trio, ang)
        wg = np.where(oko, go * areao, 0)
        instrip = np.abs(so - axis) <= fg.STRIP / 2
        if wg[instrip].sum() / wg.sum() >= target:
            break
    out["onset_travel"] = float(sr.travel[k1o])
    half = math.sqrt(max(R_USABLE**2 - axis**2, sr.d**2))  # the strip's half chord
    te = np.arange(-half, half + sr.d, sr.d)
    num, _ = np.histogram(to[instrip], te, weights=wg[instrip])
    num = np.convolve(num, np.ones(3) / 3, "same")
    tpk = 0.5 * (te[1:] + te[:-1])[int(np.argmax(num))]
    out["onset_wall_d"] = max(0.0, R_USABLE - math.hypot(tpk, axis)) / sr.d  # (a bin's centre may lie past the chord's end)
    # the host's ring where the band's axis meets the cavity, against the mirror points
    ha, hb = sr.r.field("host_ring", k0 - 1), sr.r.field("host_ring", k1)
    dexx, deyy, dexy = (hb[c] - ha[c] for c in ("exx", "eyy", "exy"))
    gam = 2 * np.hypot(0.5 * (dexx - deyy), dexy)
    R = 2.5
    tend = math.sqrt(max(R**2 - axis**2, 0))
    nrm = np.array([-math.sin(th), math.cos(th)])
    tan = np.array([math.cos(th), math.sin(th)])
    at_end, at_mirror = [], []
    for sgn in (-1, 1):
        p = axis * nrm + sgn * tend * tan
        for pt, lst in ((p, at_end), (p * [-1, 1], at_mirror)):
            dd = np.hypot(ha["x"] - pt[0], ha["y"] - pt[1])
            lst.extend(gam[np.argsort(dd)[:2]])
    out["host_end_mirror"] = float(np.mean(at_end) / np.mean(at_mirror))
    # the same on the wall itself (the elements' shear strain |eps_t - eps_n| from the hoop and
    # normal stress, plane strain), the two elements nearest each end against their mirrors
    wa, wb = sr.r.field("host_wall", k0 - 1), sr.r.field("host_wall", k1)
    gw = np.abs((wb["hoop"] - wa["hoop"]) - (wb["normal"] - wa["normal"])) / (2 * study.G)
    at_end, at_mirror = [], []
    for sgn in (-1, 1):
        p = axis * nrm + sgn * tend * tan
        for pt, lst in ((p, at_end), (p * [-1, 1], at_mirror)):
            lst.extend(gw[np.argsort(np.hypot(wa["x"] - pt[0], wa["y"] - pt[1]))[:2]])
    out["wall_end_mirror"] = float(np.mean(at_end) / np.mean(at_mirror))
    out["host_end_mean"] = float(np.mean(at_end) / np.mean(gam))
    out["ring_max"] = sr.ring[sr.last]
    out["wall_max"] = sr.wall[sr.last]
    if SCALE:   # the followed host's cavity against the boundary particles' rest shapes
        stretch, turn, dl = particle_mismatch(sr.run)
        out["particle_stretch"], out["particle_turn"], out["particle_gap_d"] = stretch, turn, dl / sr.d
    out["_draw"] = (tri, g, ok, ha["x"], ha["y"], gam, gb, ang, axis)
    return out


KEYS = [("travel", "top's travel within the allowed host strain [cm]", "{:.3f}"),
        ("wall_max", "host's largest principal strain on the wall at the last step measured", "{:.4f}"),
        ("ring_max", "the same on the ring at 1.5 R", "{:.4f}"),
        ("p_zone_P", "zone's mean pressure at the end of the confinement / P", "{:.3g}"),
        ("zone_axial", "zone's vertical strain over the allowed travel (compression +)", "{:.4f}"),
        ("zone_vol", "zone's volumetric strain over it (dilation +)", "{:.4f}"),
        ("band", "band measure at the band's time", "{:.2f}"),
        ("band_null", "the same window's (strain, area) shuffled among its triangles (null)", "{:.2f}"),
        ("band_whole", "band measure of the whole allowed travel", "{:.2f}"),
        ("axis_r", "band axis' distance from the centre / usable radius", "{:.2f}"),
        ("band_travel", "band's time: travel at the window's end [cm]", "{:.3f}"),
        ("phi", "mobilised friction angle phi [deg]", "{:.1f}"),
        ("psi", "dilatancy angle psi [deg]", "{:.1f}"),
        ("theta", "band to the minor principal stress direction [deg]", "{:.1f}"),
        ("theta_mc", "theta_MC = 45 + phi/2 [deg]", "{:.1f}"),
        ("theta_r", "theta_R = 45 + psi/2 [deg]", "{:.1f}"),
        ("theta_a", "theta_A = 45 + (phi + psi)/4 [deg]", "{:.1f}"),
        ("thickness_d", "thickness (FWHM of the shear strain profile) [d]", "{:.1f}"),
        ("rot_ratio", "mean abs rotation in the band / outside", "{:.2f}"),
        ("rot_ratio_null", "the same for random strips as wide (null)", "{:.2f}"),
        ("rot_ratio_med", "median abs rotation in the band / outside", "{:.2f}"),
        ("rot_ratio_med_null", "the same for random strips as wide (null)", "{:.2f}"),
        ("onset_wall_d", "onset: distance of the strain peak from the wall [d]", "{:.1f}"),
        ("wall_end_mirror", "host wall's shear strain increment at the band's ends / mirror points", "{:.2f}"),
        ("host_end_mirror", "host ring's (1.5 R) shear strain increment at the band's ends / mirror points", "{:.2f}"),
        ("host_end_mean", "the same / the ring's mean", "{:.2f}")]
if SCALE:   # the followed host (particle_mismatch)
    KEYS += [("particle_stretch", "cavity elements at the end: largest stretch against the boundary particles' rest size", "{:.3f}"),
             ("particle_gap_d", "the same as a length, over the mean grain diameter", "{:.3f}"),
             ("particle_turn", "cavity elements at the end: largest turn against the particles' rest normal [deg]", "{:.1f}")]


# the band network measures (network_run), in the table after the others and at the end of the CSV
NET_KEYS = [("net_ratio", "profile contrast / its block null, largest over the windows (without overlap)", "{:.2f}"),
            ("net_ratio_shuffled", "the same window's profile contrast / its shuffled null", "{:.2f}"),
            ("net_ratio2", "the same window's next direction family: contrast / block null", "{:.2f}"),
            ("net_travel", "that window's end: travel [cm]", "{:.3f}"),
            ("net_band_windows", f"windows with profile contrast >= {BAND_BLOCK} x block null", "{:.1f}"),
            ("net_windows", "windows without overlap", "{:.1f}"),
            ("net_whole_ratio", "profile contrast / block null of the whole travel", "{:.2f}"),
            ("share_d_ratio", f"{fg.BAND_D:g} d strip share / its shuffled null, largest over the windows", "{:.2f}"),
            ("share_d_whole_ratio", f"{fg.BAND_D:g} d strip share / its null of the whole travel", "{:.2f}")]


def case_label(group):
    _, k, p, r = next(g for g in GROUPS if g[0] == group)
    return f"kn/G {k:g} cm, P {p:g}, {'rolling' if r else 'no rolling'}"


def mean_row(by, groups, key, label, fmt):
    """A table row: the key's mean +- sd (count) over each group's runs (by: group -> rows)."""
    cells = []
    for g in groups:
        v = np.array([r[key] for r in by[g] if key in r and np.isfinite(r[key])])
        cells.append(f"{fmt.format(v.mean())} +- {fmt.format(v.std(ddof=1))} ({len(v)})" if len(v) > 1
                     else f"{fmt.format(v[0])} (1)" if len(v) else "")
    return f"| {label} | " + " | ".join(cells) + " |"


def table(rows):
    groups = [g[0] for g in GROUPS]
    head = "| measure | " + " | ".join(f"{g}" for g in groups) + " |\n|---|" + "---|" * len(groups) + "\n"
    lines = []
    by = {g: [r for r in rows if r["case"].startswith(g + "/")] for g in groups}
    lines.append("| runs measured (of " + str(SEEDS) + ") | "
                 + " | ".join(str(sum("band" in r for r in by[g])) for g in groups) + " |")
    lines.append(f"| runs with band measure >= {EPISODE} | "
                 + " | ".join(str(sum(r.get("band", 0) >= EPISODE for r in by[g])) for g in groups) + " |")
    lines.append(f"| runs with band measure >= {EPISODE} and >= 2 x its null | "
                 + " | ".join(str(sum(r.get("band", 0) >= max(EPISODE, 2 * r.get("band_null", 1)) for r in by[g]))
                              for g in groups) + " |")
    lines.append("| runs with band measure >= 2 x its null | "
                 + " | ".join(str(sum(r.get("band", 0) >= 2 * r.get("band_null", 1) for r in by[g])) for g in groups)
                 + " |")
    lines.append("| runs with the onset's strain peak within 3 d of the wall | "
                 + " | ".join(str(sum(r.get("onset_wall_d", 99) <= 3 for r in by[g])) for g in groups) + " |")
    lines += [mean_row(by, groups, *k) for k in KEYS]
    # the measured orientation against each prediction: mean (sd) of the difference
    for key, name in (("theta_mc", "MC"), ("theta_r", "R"), ("theta_a", "A")):
        cells = []
        for g in groups:
            v = np.array([r["theta"] - r[key] for r in by[g] if "theta" in r])
            cells.append(f"{v.mean():+.1f} +- {v.std(ddof=1):.1f} ({len(v)})" if len(v) > 1 else "")
        lines.append(f"| theta - theta_{name} [deg] | " + " | ".join(cells) + " |")
    # the band network measures (after the others: their rows stay where they were)
    lines.append(f"| runs with profile contrast >= {BAND_BLOCK} x its block null in a window | "
                 + " | ".join(str(sum(r.get("net_band_windows", 0) >= 1 for r in by[g])) for g in groups) + " |")
    lines.append("| runs with it in two windows in a row, in one direction to 15 deg (a band forms) | "
                 + " | ".join(str(sum(r.get("net_longest", 0) >= 2 for r in by[g])) for g in groups) + " |")
    lines += [mean_row(by, groups, *k) for k in NET_KEYS]
    legend = "\n".join(f"- `{g}`: {case_label(g)}" for g in groups)
    where = ("on the cavity wall" if BOUND_AT == "wall" else "on the ring at 1.5 R (the wall's reaches about twice "
             "as much)")
    bound = ("each run measured over its whole travel (the host follows its deformed boundary)" if SCALE else
             f"each run measured up to its last step with the host's largest principal strain {where} <= "
             f"{study.STAT_HOST_STRAIN:g}")
    return (f"Mean +- standard deviation (number of runs) over the packings; {bound} "
            f"(band_statistics.py; windows of {WINDOW} steps of 0.01 cm, or all the allowed steps when fewer).\n\n" + head + "\n".join(lines) + "\n\n"
            + legend + "\n")


def draw_band(ax, sr, m, vmax, extent=3.9, outlines=True):
    """The window's shear strain on its triangles, the grains' outlines (if asked), the band
    measure's strip (dashed) and, with a host (hx not None), the host's strain on its ring; the
    axes span +-extent."""
    tri, g, ok, hx, hy, hg, gb, ang, axis = m["_draw"]
    tp = ax.tripcolor(tri, facecolors=np.where(ok, g, 0), cmap="inferno", vmin=0, vmax=vmax)
    hs = None if hx is None else ax.scatter(hx, hy, c=hg, cmap="Greys", vmin=0, vmax=np.percentile(hg, 98), s=14,
                                            marker="s", edgecolors="k", linewidths=0.2)
    if outlines:
        ax.add_collection(PatchCollection([Circle((x, y), r) for x, y, r in zip(gb["x"], gb["y"], sr.radii)],
                                          facecolor="none", edgecolor="0.6", linewidths=0.15))
    th = math.radians(ang)
    nrm, tan = np.array([-math.sin(th), math.cos(th)]), np.array([math.cos(th), math.sin(th)])
    for off in (-fg.STRIP / 2, fg.STRIP / 2):
        p = (axis + off) * nrm
        ax.plot(*np.array([p - 3 * tan, p + 3 * tan]).T, color="tab:cyan", lw=0.6, ls="--")
    ax.set_aspect("equal")
    ax.set_xlim(-extent, extent), ax.set_ylim(-extent, extent)
    ax.set_xticks([]), ax.set_yticks([])
    return tp, hs


def fig_maps(runs, meas):
    """Per case, the run whose band measure is the case's median: the band's window."""
    groups = [g[0] for g in GROUPS]
    fig, axes = plt.subplots(*((2, 2) if SCALE else (2, 4)), figsize=(10, 10.5) if SCALE else (13, 7.2))
    for ax, grp in zip(axes.ravel(), groups):
        ms = [m for m in meas if m["case"].startswith(grp + "/") and "band" in m]
        if not ms:
            ax.axis("off")
            continue
        order = np.argsort([m["band"] for m in ms])
        m = ms[order[len(order) // 2]]
        if m["case"] not in runs:
            sys.exit(f"{OUT}_maps.png: the median run of {grp}, {m['case']}, is kept from {OUT}_runs.csv; "
                     f"its directory is needed in {RUNS} for its map (run it, then again)")
        sr = runs[m["case"]]
        tp, _ = draw_band(ax, sr, m, np.percentile(m["_draw"][1][m["_draw"][2]], 98))
        ax.set_title(f"{case_label(grp)}\n{m['case'].split('/')[-1]}: window to {m['band_travel']:.2f} cm, "
                     f"band {m['band']:.2f} at {m['ang']:.0f} deg\nthickness {m['thickness_d']:.1f} d, "
                     f"rotation ratio {m['rot_ratio']:.2f}", fontsize=7)
        fig.colorbar(tp, ax=ax, fraction=0.04, pad=0.01)
    fig.suptitle("The band's window (shear strain accumulated over 0.05 cm of the top's travel) of the run with the "
                 "median band measure of each case\ndashed: the band measure's 0.5 cm strip; grey squares: the host's "
                 "shear strain increment over the window on the ring at 1.5 R (own scale)", fontsize=8)
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    path = os.path.join(HERE, f"{OUT}_maps.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    fg.shrink_png(path)


def fig_measures(meas):
    groups = [g[0] for g in GROUPS]
    panels = [("theta", "band to minor principal stress [deg]"), ("band", "band measure"),
              ("thickness_d", "thickness [d]"), ("rot_ratio_med", "median rotation in band / outside"),
              ("onset_wall_d", "onset distance from the wall [d]"),
              ("wall_end_mirror", "host wall at band ends / mirror points")]
    fig, axes = plt.subplots(2, 3, figsize=(13, 7.5))
    x = np.arange(len(groups))
    for ax, (key, label) in zip(axes.ravel(), panels):
        for i, grp in enumerate(groups):
            v = np.array([m[key] for m in meas if m["case"].startswith(grp + "/") and key in m])
            jit = (np.random.default_rng(i).random(len(v)) - 0.5) * 0.3
            ax.plot(i + jit, v, ".", color="tab:blue", ms=4)
            if len(v):
                ax.errorbar(i + 0.3, v.mean(), v.std(ddof=1) if len(v) > 1 else 0, fmt="s", color="k", ms=4)
            nk = {"band": "band_null", "rot_ratio_med": "rot_ratio_med_null"}.get(key)
            if nk:
                vn = np.array([m[nk] for m in meas if m["case"].startswith(grp + "/") and nk in m])
                ax.plot(i + 0.3, np.nanmean(vn), "x", color="tab:red", ms=6,
                        label="null (mean)" if i == 0 else None)
            if key == "theta":
                for k2, col in (("theta_mc", "tab:red"), ("theta_r", "tab:green"), ("theta_a", "tab:orange")):
                    p = np.array([m[k2] for m in meas if m["case"].startswith(grp + "/") and k2 in m])
                    if len(p):
                        ax.plot([i - 0.35, i + 0.4], [p.mean()] * 2, color=col, lw=1.2,
                                label={"theta_mc": "MC 45+phi/2", "theta_r": "Roscoe 45+psi/2",
                                       "theta_a": "Arthur 45+(phi+psi)/4"}[k2] if i == 0 else None)
        if key in ("theta", "band", "rot_ratio_med"):
            ax.legend(fontsize=6)
        if key == "band":
            ax.axhline(EPISODE, color="0.5", ls=":", lw=0.8)
        if key in ("rot_ratio_med", "wall_end_mirror"):
            ax.axhline(1, color="0.5", ls=":", lw=0.8)
        if key == "thickness_d":
            ax.axhspan(7.5, 10, color="0.9", zorder=0)
            ax.set_ylim(0, None)
        if key == "theta":   # a direction at random: uniform in 0-90 deg, mean 45, sd 26
            ax.axhspan(45 - 26, 45 + 26, color="0.93", zorder=0)
        ax.set_xticks(x)
        ax.set_xticklabels(groups, rotation=30, fontsize=6)
        ax.set_ylabel(label, fontsize=8)
    fig.suptitle("Per run (dots) and mean +- sd per case (squares); grey in the thickness panel: 7.5-10 d "
                 "(Bardet & Proubet 1992, discs); in the orientation panel: 45 +- 26 deg, a direction drawn at random",
                 fontsize=8)
    fig.tight_layout(rect=(0, 0, 1, 0.96))
    fig.savefig(os.path.join(HERE, f"{OUT}_measures.png"), dpi=110)
    plt.close(fig)


def kept_rows():
    """The rows of the last <out>_runs.csv by run name (numbers as floats, empty cells left out)."""
    path = os.path.join(HERE, f"{OUT}_runs.csv")
    if not os.path.exists(path):
        return {}
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {r["case"]: {"case": r["case"], **{k: float(v) for k, v in r.items() if k != "case" and v != ""}}
            for r in rows}


def differs(m, kept):
    """The largest relative difference between a run's measures and its kept row, and its key."""
    d = [(abs(m[k] - v) / max(abs(v), 1e-12), k) for k, v in kept.items()
         if k in m and isinstance(m[k], (int, float, np.number))]
    return max(d, default=(0.0, ""))


def main():
    names = [c[0] for c in CASES]
    kept = kept_rows() if KEEP else {}
    runs, meas = {}, []
    for n in names:
        st = os.path.join(RUNS, n, "status.yaml") if SCALE else os.path.join(RUNS, "statistics", n, "status.yaml")
        if not os.path.exists(st) or read_yaml(st).get("status") != "completed":
            print(f"{n}: kept from {OUT}_runs.csv" if n in kept else f"{n}: not completed, skipped")
            if n in kept:
                meas.append(kept[n])
            continue
        sr = StatRun(n)
        runs[n] = sr
        meas.append(measure(sr))
        if n in kept:
            rel, key = differs(meas[-1], kept[n])
            print(f"{n}: measured again; largest relative difference to its kept row {rel:.2g} ({key or '-'})")
    with open(os.path.join(HERE, f"{OUT}.md"), "w") as f:
        f.write(table(meas))
    keys = [k for k, _, _ in KEYS] + ["window", "spinning", "rattlers", "strip_ang", "ang", "minor_dir", "axis", "onset_travel", "d"]
    keys += [k for k, _, _ in NET_KEYS] + ["net_contrast", "net_ang", "net_ang2", "net_longest"]
    with open(os.path.join(HERE, f"{OUT}_runs.csv"), "w") as f:
        f.write("case," + ",".join(keys) + "\n")
        for m in meas:
            f.write(m["case"] + "," + ",".join(f"{m[k]:.6g}" if k in m else "" for k in keys) + "\n")
    fig_measures(meas)
    fig_maps(runs, meas)
    print(open(os.path.join(HERE, f"{OUT}.md")).read())


if __name__ == "__main__":
    main()
