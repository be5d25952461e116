#!/usr/bin/python3
"""The localisation study's cases and scenes (used by run_study.sh and figures.py).

A 10 x 10 cm elastic square (meshes/square_cavity_sides.geo: 16 elements a side, 64 on the cavity
of radius 2.5 cm; shear modulus G = 95000 kgf/cm^2, Poisson 0.1, plane strain) in biaxial
compression: bottom fixed, a confining pressure P on the left and right grown in STEPS_P steps
with the top held, then the top (ux = 0) pushed down by DUY per step for STEPS steps. The cavity
holds N grains packed by pack_cavity.py to a solid fraction phi; kn between grains and against the
boundary particles, kt = 0.7 kn between grains (none against the particles, frictionless).

The sweep varies one parameter at a time around the base case (phi 0.82, 30 deg, kn/G = 0.1 cm):
grain friction 0 / 15 / 30 deg, solid fraction 0.78 / 0.82 / 0.85, kn/G 0.01 / 0.1 / 1 cm.

Usage: study.py cases                 one line per case: name phi friction kn
       study.py scene NAME DIR MESH [R] writes DIR/scene.yaml (R > 1: DIR/scene_refineR.yaml, the
                                      top's steps R times smaller); the grains file: DIR/grains.csv
       study.py disc_moduli           one line per reference disc: name shear_modulus poisson
       study.py load                  P STEPS_P top displacement STEPS (for elastic_disc)
"""
import math
import sys

G, NU = 95000.0, 0.1
N_GRAINS, SEED = 250, 1
P, STEPS_P = 100.0, 2
DUY, STEPS = -0.01, 100
KT_KN = 0.7
A_KN = 5e-5  # the accuracy a = A_KN x kn (cm): about 0.5 % of the mean contact force at the end
A_FRICTIONLESS = 2e-4  # frictionless grains: with A_KN a load step stalls (two contacts, no friction)
BASE = {"phi": 0.82, "friction": 30.0, "kn_g": 0.1}
SWEEP = {"friction": [0.0, 15.0, 30.0], "phi": [0.78, 0.82, 0.85], "kn_g": [0.01, 0.1, 1.0, 10.0]}
Z_VOIGT = 4.0  # coordination number assumed for the equivalent disc


def case_name(phi, friction, kn_g):
    return f"phi{phi:.2f}_f{friction:02.0f}_k{kn_g:g}"


def cases():
    """(name, phi, friction, kn) in sweep order, each once; the base case first."""
    out, seen = [], set()
    for key in ["friction", "phi", "kn_g"]:
        for v in SWEEP[key]:
            c = dict(BASE)
            c[key] = v
            name = case_name(c["phi"], c["friction"], c["kn_g"])
            if name not in seen:
                seen.add(name)
                out.append((name, c["phi"], c["friction"], c["kn_g"] * G))
    base = case_name(BASE["phi"], BASE["friction"], BASE["kn_g"])
    out.sort(key=lambda c: c[0] != base)
    return out


def voigt_disc(kn, phi=BASE["phi"], z=Z_VOIGT):
    """The Voigt (affine) moduli of an isotropic 2D disc assembly: G = z phi (kn + kt) / (4 pi),
    lambda = z phi (kn - kt) / (4 pi) per unit depth (1 cm); the plane strain Poisson ratio
    lambda / (2 (lambda + G)) = (1 - kt/kn) / 4."""
    kt = KT_KN * kn
    g = z * phi * (kn + kt) / (4 * math.pi)
    return g, (1 - KT_KN) / 4


def disc_moduli():
    out = [("homogeneous", G, NU)]
    for kn_g in SWEEP["kn_g"]:
        g, nu = voigt_disc(kn_g * G)
        out.append((f"voigt_k{kn_g:g}", g, nu))
    return out


SCENE = """\
# The localisation study (validation/localisation/study.py writes this scene): {name}
gembem: 1
units: {{length: cm, force: kgf}}
materials:
  grain_grain: {{kn: {kn:g}, kt: {kt:g}, friction_deg: {friction:g}}}
  grain_wall: {{kn: {kn:g}, kt: {kt:g}, friction_deg: 0}}          # unused: the host replaces the walls
  grain_boundary: {{kn: {kn:g}, kt: 0, friction_deg: 0}}
host:
  mesh: {mesh}
  elements: {{bottom: 16, right: 16, top: 16, left: 16, cavity: 64}}
  material: {{shear_modulus: {G:g}, poisson: {NU:g}, plane: strain}}
  boundary: {{bottom: fixed, top: displacement, left: {{pressure: 0}}, right: {{pressure: 0}}}}
  cavity: cavity
grains:
  file: grains.csv           # pack_cavity.py --n {n} --phi {phi} --seed {seed}
solver: {{method: global, linear: cholmod, accuracy: {a:g}, max_iterations: 3000}}
loading:
  - relax: {{steps: 1}}
  - host_load: {{steps: {steps_p}, increments: {{left: {dp:g}, right: {dp:g}}}}}
  - host_load: {{steps: {steps}, increments: {{top: [0, {duy:g}]}}}}
"""


def scene(name, mesh, refine=1):
    """The case's scene; refine > 1: the top's steps `refine` times smaller (a second attempt)."""
    for n, phi, friction, kn in cases():
        if n == name:
            return SCENE.format(name=name, kn=kn, kt=KT_KN * kn, friction=friction, mesh=mesh, G=G, NU=NU,
                                n=N_GRAINS, phi=phi, seed=SEED, a=kn * (A_FRICTIONLESS if friction == 0 else A_KN),
                                steps_p=STEPS_P, dp=P / STEPS_P, steps=STEPS * refine, duy=DUY / refine)
    raise SystemExit(f"unknown case {name}")


def main():
    if sys.argv[1] == "cases":
        for n, phi, friction, kn in cases():
            print(n, phi, friction, kn)
    elif sys.argv[1] == "scene":
        refine = int(sys.argv[5]) if len(sys.argv) > 5 else 1
        with open(f"{sys.argv[3]}/scene{'' if refine == 1 else f'_refine{refine}'}.yaml", "w") as f:
            f.write(scene(sys.argv[2], sys.argv[4], refine))
    elif sys.argv[1] == "disc_moduli":
        for n, g, nu in disc_moduli():
            print(n, f"{g:.6g}", f"{nu:.6g}")
    elif sys.argv[1] == "load":
        print(P, STEPS_P, DUY * STEPS, STEPS)


if __name__ == "__main__":
    main()
