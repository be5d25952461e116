#!/usr/bin/python3
"""The localisation study's control: the statistics' packing in a plain biaxial box of walls, of the
cavity's size, strained as far as the study wants to go. Does a band form where 2D DEM says one
does, and do the band measures (band_statistics.py, through box_bands.py) find it?

The case is study.py's statistics case (k0.01_p100_nr: kn/G = 0.01 cm, no rolling) at N grains,
with its grain size distribution, contact law (kn, kt = 0.7 kn, 30 deg between grains; with
--rolling the statistics' rolling resistance), packing protocol (gembem pack: growth, frictionless,
to the solid fraction 0.82 of the region) and solver (global, accuracy 1e-3 of the mean normal
contact force), all taken from study.py. What changes:

- The region: a square box whose side is the usable diameter of the hybrid case's cavity at N
  (2 R_u: the cavity's radius 2.5 cm less its boundary particles' bulge, with M = 128 cavity
  elements per 1000 grains' sqrt, 128 at N = 1000 and 384 at 10 000 as scale_probe.py), and grains
  of the hybrid case's mean size at N (study.stat_r0(N, M)). The box is then as many grains across
  as the cavity (35 d at N = 1000, 113 d at 10 000) and a band of given width in d has the same
  room; the box holds 4 N / pi grains (1273 for 1000: its corners), not N. The walls are smooth
  (the study's grain_wall law, friction 0), as a biaxial test's lubricated platens.
- The confinement: the hybrid zone's mean pressure after its confinement, measured by
  band_statistics.py (Love-Weber stress over the usable disc): 0.011 P with P = 100 kgf/cm^2 at
  kn/G = 0.01 cm (0.0110 +- 0.0023 over the 20 packings of k0.01_p100_nr), i.e. 1.1 kgf/cm on the
  walls (2D, per unit depth: F/L, the host's kgf/cm^2 times 1 cm); 2.25 P = 225 kgf/cm at kn/G =
  10 cm (2.2-2.3 P in the statistics). Another kn/G needs --stress.
- The loading: a relaxation (the pack's grains with friction switched on, walls held), the
  isotropic compression to that stress in 2 steps, then gembem's `shear_mean_stress`: each step
  d(e1 - e2) = 0.0025, the mean wall stress restored to the confining stress. That is the paper's
  biaxial test at constant mean stress; a biaxial test at constant lateral stress under vertical
  strain control is not among gembem's stages (docs/scene.md: `strain` moves both pairs of walls,
  `biaxial_stress` controls both stresses). 0.0025 a step is the statistics' rate: their zone
  reached e1 - e2 = 0.020 in 8 steps (vertical 1.52 %, volumetric -1.0 %). 120 steps: e1 - e2 =
  0.30, a vertical strain of 0.15 less half the dilation.
- Output: fields/ and contacts/ every step (the strain on the triangles, the rotations, the
  coordination that box_bands.py reads).

Usage: validation/localisation/biaxial_control.py N DIR [BUILD_DIR] [--seed S] [--rolling]
           [--kn-g K] [--stress S] [--steps K] [--measure-only]
Writes DIR/pack.yaml, DIR/pack/, DIR/grains.csv, DIR/scene.yaml, the run DIR/run/ and the band
measures of box_bands.py (DIR/bands.md, DIR/bands.csv, DIR/bands.png). --measure-only: the
measures of an existing DIR/run."""
import argparse
import math
import os
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "python"))
sys.path.insert(0, HERE)
import gembem  # noqa: E402
import study  # noqa: E402
from gembem import read_state, write_grains_csv  # noqa: E402

P_ZONE = {0.01: 0.011, 10.0: 2.25}   # the hybrid zone's mean pressure after its confinement / P, per kn/G [cm]
D_SHEAR = 0.0025                     # d(e1 - e2) per step: the statistics' zone's rate
STEPS = 120                          # e1 - e2 = 0.30


def cavity_elements(n):
    """The hybrid case's cavity elements at n grains: 128 at 1000 (the statistics), 384 at 10 000
    (scale_probe.py), the boundary particles' size following the grains'."""
    return 128 * max(1, round(math.sqrt(n / 1000)))


def geometry(n):
    """(grains in the box, the box's side [cm], the hybrid case's mean radius r0 [cm]) at n grains."""
    m = cavity_elements(n)
    return round(4 * n / math.pi), 2 * study.usable_radius(m), study.stat_r0(n, m)


def box(side):
    h = study.g6(side / 2)
    return {"left": -h, "right": h, "bottom": -h, "top": h}   # centred: the strain moves the walls symmetrically


def pack_scene(n, seed, kn_g):
    count, side, _ = geometry(n)
    kn = kn_g * study.G
    s = gembem.Scene(units={"length": "cm", "force": "kgf"}, materials=study.materials(kn, 0), box=box(side),
                     solver=study.pack_solver(kn), extra={"pack": study.pack_section(count, study.BASE["phi"], seed)})
    return s, (f"The localisation study's control (validation/localisation/biaxial_control.py writes this pack "
               f"scene): the packing of the statistics' case at {n} grains (study.pack_section) in a box "
               f"of the cavity's usable diameter, seed {seed}, kn/G {kn_g:g} cm")


def run_scene(n, kn_g, rolling, stress, steps):
    _, side, r0 = geometry(n)
    mat = study.materials(kn_g * study.G, study.BASE["friction"])
    if rolling:
        mat["grain_grain"]["rolling"] = study.stat_rolling(kn_g, r0)
    return gembem.Scene(units={"length": "cm", "force": "kgf"}, materials=mat, grains={"file": "grains.csv"},
                        box=box(side), solver=study.stat_solver(),
                        loading=[{"relax": {"steps": 1}},
                                 {"isotropic": {"stress": study.g6(stress), "steps": study.STEPS_P}},
                                 {"shear_mean_stress": {"d_e1_minus_e2": D_SHEAR, "mean_stress": study.g6(stress),
                                                        "steps": steps}}],
                        output={"contacts_every": 1, "measures_every": 1})


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0], usage=__doc__.split("Usage: ")[1].split("\n\n")[0])
    ap.add_argument("n", type=int)
    ap.add_argument("dir")
    ap.add_argument("build", nargs="?", default=os.path.join(ROOT, "build"))
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--rolling", action="store_true")
    ap.add_argument("--kn-g", type=float, default=0.01)
    ap.add_argument("--stress", type=float, help="the confining stress [kgf/cm]; default P_ZONE[kn/G] x P")
    ap.add_argument("--steps", type=int, default=STEPS)
    ap.add_argument("--measure-only", action="store_true")
    a = ap.parse_args()
    if a.stress is None and a.kn_g not in P_ZONE:
        ap.error(f"--kn-g {a.kn_g:g}: no measured zone pressure for it (known: {sorted(P_ZONE)}); give --stress")
    stress = a.stress if a.stress is not None else P_ZONE[a.kn_g] * study.P
    exe = os.path.join(a.build, "gembem")
    d = a.dir
    if not a.measure_only:
        os.makedirs(d, exist_ok=True)
        s, comment = pack_scene(a.n, a.seed, a.kn_g)
        s.write(os.path.join(d, "pack.yaml"), comment=comment)
        t0 = time.time()
        subprocess.run([exe, "pack", os.path.join(d, "pack.yaml"), "-o", os.path.join(d, "pack"), "--overwrite"],
                       check=True)
        t_pack = time.time() - t0
        g = read_state(os.path.join(d, "pack")).grains
        write_grains_csv(os.path.join(d, "grains.csv"), np.column_stack([g["x"], g["y"], g["r"]]))
        run_scene(a.n, a.kn_g, a.rolling, stress, a.steps).write(
            os.path.join(d, "scene.yaml"),
            comment=(f"The localisation study's control (validation/localisation/biaxial_control.py writes this "
                     f"scene): {a.n} grains' worth of the statistics' case in a biaxial box, seed {a.seed}, kn/G "
                     f"{a.kn_g:g} cm, {'rolling' if a.rolling else 'no rolling'}, confined at {stress:g} kgf/cm"))
        t0 = time.time()
        subprocess.run([exe, "run", os.path.join(d, "scene.yaml"), "-o", os.path.join(d, "run"), "--overwrite"],
                       check=True)
        print(f"biaxial_control: pack {t_pack:.1f} s, run {time.time() - t0:.1f} s (wall)")
    import box_bands   # matplotlib and the measures: only when measuring
    box_bands.main(d, d)


if __name__ == "__main__":
    main()
