#!/usr/bin/python3
"""The localisation study's cases and scenes (used by the Snakefile, run_continued.py and figures.py).

A 10 x 10 cm elastic square (meshes/square_cavity_sides.geo: 16 elements a side, 64 on the cavity
of radius 2.5 cm; shear modulus G = 95000 kgf/cm^2, Poisson 0.1, plane strain) in biaxial
compression: bottom fixed, a confining pressure P on the left and right grown in STEPS_P steps
with the top held, then the top (ux = 0) pushed down by DUY per step for STEPS steps. The cavity
holds N grains packed by gembem pack (pack_scene) to a solid fraction phi; kn between grains and against the
boundary particles, kt = 0.7 kn between grains (none against the particles, frictionless).

The sweep varies one parameter at a time around the base case (phi 0.82, 30 deg, kn/G = 0.1 cm):
grain friction 0 / 15 / 30 deg, solid fraction 0.78 / 0.82 / 0.85, kn/G 0.01 / 0.1 / 1 cm.

The extended cases (EXTENDED, below) leave the sweep to look for a persistent shear band: more
travel, more grains, simple shear of the body, a nearly incompressible host, a low confinement.

Usage: study.py cases                 one line per case: name phi friction kn
       study.py extended              one line per extended case: name load n kn_g nu P
       study.py pack NAME             the case's packing in one line (pack_args)
       study.py pack_scene NAME MESH  the case's pack scene (gembem pack)
       study.py scene NAME DIR MESH [R] writes DIR/scene.yaml (R > 1: DIR/scene_refineR.yaml, the
                                      top's steps R times smaller); the grains file: DIR/grains.csv
       study.py disc_moduli           one line per reference disc: name shear_modulus poisson
       study.py load                  P STEPS_P top displacement STEPS (for elastic_disc)
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import gembem  # noqa: E402

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


def g6(v):
    """v to 6 significant digits (%g): the numbers the study's scenes have always held."""
    return float(f"{v:g}")


def materials(kn, friction):
    """The contact laws of a case's scenes: kn, kt = KT_KN kn and the friction between grains;
    frictionless walls (smooth platens: the box of biaxial_control.py; unused with a host) and
    boundary particles (normal springs only)."""
    kn, kt = g6(kn), g6(KT_KN * kn)
    return {"grain_grain": {"kn": kn, "kt": kt, "friction_deg": g6(friction)},
            "grain_wall": {"kn": kn, "kt": kt, "friction_deg": 0},
            "grain_boundary": {"kn": kn, "kt": 0, "friction_deg": 0}}


def host(kn, friction, mesh, cavity, nu, top_bc):
    """The materials and the host of a case's scenes (the run's and the packing's), as a Scene's
    sections; top_bc: the top's boundary condition ("displacement" or {"ux": 0, "ty": 0})."""
    body = {"mesh": mesh, "elements": {"bottom": 16, "right": 16, "top": 16, "left": 16, "cavity": cavity},
            "material": {"shear_modulus": g6(G), "poisson": g6(nu), "plane": "strain"},
            "boundary": {"bottom": "fixed", "top": top_bc, "left": {"pressure": 0}, "right": {"pressure": 0}},
            "cavity": "cavity"}
    return {"materials": materials(kn, friction), "host": body}


def case_scene(name, kn, friction, mesh, cavity, nu, top_bc, a, max_it, dp, top_p, steps, du):
    """A case's scene: the host, the grains of grains.csv, a relaxation, the confinement dp per
    step (top_p: also on the top, as a traction), then the top moved by du = [dux, duy] per step."""
    inc = {"left": g6(dp), "right": g6(dp)}
    if top_p is not None:
        inc["top"] = [0, g6(top_p)]
    return gembem.Scene(units={"length": "cm", "force": "kgf"}, **host(kn, friction, mesh, cavity, nu, top_bc),
                        grains={"file": "grains.csv"},
                        solver={"method": "global", "accuracy": g6(a), "max_iterations": max_it},
                        loading=[{"relax": {"steps": 1}}, {"host_load": {"steps": STEPS_P, "increments": inc}},
                                 {"host_load": {"steps": steps, "increments": {"top": [g6(v) for v in du]}}}])


def scene_comment(name):
    """What a case's scene is (its first lines)."""
    return (f"The localisation study (validation/localisation/study.py writes this scene): {name}\n"
            f"grains.csv: gembem pack of pack.yaml ({pack_args(name)})")


# Extended cases (the second part of the study): one at a time away from the sweep, to look for a
# persistent shear band. Keys not given take the base case's / the sweep's values:
#   n grains (r0 follows from phi and n), cavity elements, friction, phi, kn_g, nu (host), P
#   (confinement), load "biaxial" (top pushed down, ux = 0) or "shear" (top: {ux, ty}: the
#   confinement P also on the top as a normal traction, then the top moved sideways by DU per step
#   with its normal traction held), STEPS_X steps of DU (cm) of the top's travel.
EXT_DEFAULTS = {"n": N_GRAINS, "cavity": 64, "friction": BASE["friction"], "phi": BASE["phi"], "kn_g": 0.01,
                "nu": NU, "P": P, "load": "biaxial", "steps": 300, "du": 0.01, "max_it": 3000, "seed": SEED}
EXTENDED = [
    # 1. the kn/G = 0.01 cm case of the sweep, 3 cm of travel
    ("x_k0.01_3cm", {}),
    # 2. four times the grains (r0 halved), boundary particles halved too (128 cavity elements)
    ("x_n1000_k0.01", {"n": 1000, "cavity": 128, "steps": 200}),
    # 3. simple shear of the body: top moved sideways under a normal traction P
    ("x_shear_k0.01", {"load": "shear", "steps": 200}),
    ("x_shear_k1", {"load": "shear", "kn_g": 1.0, "steps": 200}),
    # 4. a nearly incompressible host, a low confinement
    ("x_nu0.45_k0.01", {"nu": 0.45, "steps": 200}),
    ("x_p10_k0.01", {"P": 10.0, "steps": 200}),
    # grains much stiffer than the host, in simple shear
    ("x_shear_k10", {"load": "shear", "kn_g": 10.0, "steps": 200}),
    # 1000 and 2000 grains (the band of x_n1000_k0.01): stiffer contacts, nu 0.45, simple shear
    ("x_n1000_k0.1", {"n": 1000, "cavity": 128, "kn_g": 0.1, "steps": 200}),
    ("x_n1000_nu0.45_k0.01", {"n": 1000, "cavity": 128, "nu": 0.45, "steps": 200}),
    ("x_n1000_shear_k0.01", {"n": 1000, "cavity": 128, "load": "shear", "steps": 200}),
    ("x_n2000_k0.01", {"n": 2000, "cavity": 256, "steps": 200}),
    # other packings of the same case (seed 1 is x_k0.01_3cm's): is its episode the packing's?
    ("x_k0.01_seed2", {"seed": 2, "steps": 200}),
    ("x_k0.01_seed3", {"seed": 3, "steps": 200}),
    ("x_k0.01_seed4", {"seed": 4, "steps": 200}),
    ("x_k0.01_seed5", {"seed": 5, "steps": 200}),
]


A_EXT = 0.475  # kgf: the extended cases' accuracy, the base case's (0.5 % of its mean contact force at the
# end, 104 kgf) whatever kn (5e-5 kn would be 10 times stricter at kn/G = 0.01 cm); times sqrt(250 / n)
# (a grain's contact forces go with its diameter); never below 5e-5 kn


def ext_accuracy(c):
    return max(A_KN * c["kn_g"] * G, A_EXT * math.sqrt(N_GRAINS / c["n"]))


# the extended cases drawn window by window (figures.py: extended_windows_NAME.png)
EXT_WINDOW_MAPS = ["x_n1000_k0.01", "x_n2000_k0.01", "x_n1000_shear_k0.01", "x_k0.01_3cm", "x_k0.01_seed5"]


def ext(name):
    for n, over in EXTENDED:
        if n == name:
            c = dict(EXT_DEFAULTS)
            c.update(over)
            return c
    return None


def extended():
    """(name, case dict) of the extended cases."""
    return [(n, ext(n)) for n, _ in EXTENDED]


def pack_values(name):
    """(grains, solid fraction of the usable disc, seed, cavity elements) of the case's packing."""
    sc = stat_case(name)
    if sc is not None:
        return STAT_N, BASE["phi"], sc[4], STAT_CAVITY
    sc = scale_case(name)
    if sc is not None:
        return SCALE_N, BASE["phi"], sc[4], SCALE_CAVITY
    c = ext(name)
    if c is not None:
        return c["n"], c["phi"], c["seed"], c["cavity"]
    for n, phi, friction, kn in cases():
        if n == name:
            return N_GRAINS, phi, SEED, 64
    raise SystemExit(f"unknown case {name}")


def pack_args(name):
    """The case's packing in one line (the workflow repacks a case when it changes)."""
    n, phi, seed, cavity = pack_values(name)
    return f"--n {n} --phi {phi} --seed {seed} --elements {cavity}"


def pack_section(n, phi, seed):
    """The packing protocol of every case: n discs of radii uniform in [0.75, 1.25] x r0 (r0 set by
    the target), grown frictionless to the solid fraction phi of the region (gembem pack)."""
    return {"protocol": "growth", "seed": seed,
            "sizes": {"uniform": [0.75, 1.25]},   # radii, scaled to the solid fraction
            "count": n, "solid_fraction": phi}


def pack_solver(kn):
    """The packing's solver: the accuracy 5e-5 kn (the sweep's), the balance of every grain at the end."""
    return {"method": "global", "accuracy": g6(A_KN * kn)}


def pack_scene(name, mesh, radius=2.5):
    """The pack scene of the case (gembem pack -o DIR; the grains of DIR/state_grains.csv) and the
    comment saying what it is: (gembem.Scene, str). The grains are packed frictionless whatever
    the case's friction, with its kn; the accuracy is 5e-5 kn (the sweep's), the balance of every
    grain at the end of the packing."""
    n, phi, seed, cavity = pack_values(name)
    c, sc = ext(name), stat_case(name) or scale_case(name)
    kn = (sc[1] * G if sc is not None else c["kn_g"] * G if c is not None
          else next(k for m, _, _, k in cases() if m == name))
    usable = usable_radius(cavity, radius)
    polygon = 0.5 * cavity * radius**2 * math.sin(2 * math.pi / cavity)
    nu = c["nu"] if c is not None else NU
    phi_polygon = float(f"{phi * math.pi * usable**2 / polygon:.6f}")
    s = gembem.Scene(units={"length": "cm", "force": "kgf"}, **host(kn, 0, mesh, cavity, nu, "displacement"),
                     solver=pack_solver(kn), extra={"pack": pack_section(n, phi_polygon, seed)})
    comment = f"""The localisation study's packing (validation/localisation/study.py writes this pack scene): {name}
N discs of radii uniform in [0.75, 1.25] x r0 grown by gembem pack (docs/packing.md) into the
cavity, frictionless, to the solid fraction phi = {phi} of the usable disc (the cavity's radius
less the boundary particles' bulge, R cos(pi/m) - R sin(pi/m)): {phi_polygon:.6f} of the polygon."""
    return s, comment


def scene(name, mesh, refine=1):
    """The case's scene (gembem.Scene; scene_comment says what it is); refine > 1: the top's steps
    `refine` times smaller (a second attempt)."""
    if stat_case(name) is not None:
        return stat_scene(name, mesh)
    if scale_case(name) is not None:
        return scale_scene(name, mesh)
    c = ext(name)
    if c is not None:
        shear = c["load"] == "shear"
        dp = c["P"] / STEPS_P
        return case_scene(name, c["kn_g"] * G, c["friction"], mesh, c["cavity"], c["nu"],
                          {"ux": 0, "ty": 0} if shear else "displacement", ext_accuracy(c), c["max_it"], dp,
                          -dp if shear else None, c["steps"] * refine,
                          [c["du"] / refine, 0] if shear else [0, -c["du"] / refine])
    for n, phi, friction, kn in cases():
        if n == name:
            return case_scene(name, kn, friction, mesh, 64, NU, "displacement",
                              kn * (A_FRICTIONLESS if friction == 0 else A_KN), 3000, P / STEPS_P, None,
                              STEPS * refine, [0, DUY / refine])
    raise SystemExit(f"unknown case {name}")


# The statistics: 2 x 2 x 2 cases, STAT_SEEDS packings each. 1000 grains
# (the 250-grain cavity is ~18 grains across, narrower than an 8-10 d band), 128 cavity elements,
# 30 deg, phi 0.82, nu 0.1; with and without rolling resistance, P 100 and 10 kgf/cm^2, kn/G 0.01
# and 10 cm. The runs go past the host's small-strain range (STAT_STEPS); band_statistics.py reads
# only the steps within it (STAT_HOST_STRAIN on the cavity wall; --ring: on the ring at 1.5 R).
STAT_N, STAT_CAVITY, STAT_SEEDS = 1000, 128, 20
STAT_KN_G, STAT_P, STAT_ROLLING = [0.01, 10.0], [100.0, 10.0], [False, True]
STAT_HOST_STRAIN = 0.02  # the host's largest principal strain magnitude allowed (README "Statistics")
STAT_DU = 0.01           # cm of the top's travel per step
STAT_STEPS = {0.01: 24, 10.0: 24}  # steps of STAT_DU per kn/G: past the allowed strain (pilot runs: the
# ring at 1.5 R reaches 2 % at 0.17-0.18 cm of travel for both kn/G at P = 100; the wall, at 0.04-0.09)
STAT_ETA = 0.1           # rolling friction coefficient (validation/biaxial122's)
# The accuracy: a = STAT_A_REL x the mean normal contact force at each step's start (gembem's
# {relative: r}). A force (0.2375 kgf, the extended cases' rule) was up to 4.9 times the mean contact
# force of the kn/G = 0.01 cm grains, which carry little of the confinement (gembem warned).
STAT_A_REL = 1e-3


def stat_name(kn_g, p, rolling, seed):
    return f"k{kn_g:g}_p{p:g}_{'rr' if rolling else 'nr'}/s{seed:02d}"


def stat_group(kn_g, p, rolling):
    return stat_name(kn_g, p, rolling, 0).split("/")[0]


def stat_groups():
    """(group name, kn_g, P, rolling) of the 8 cases."""
    return [(stat_group(k, p, r), k, p, r) for r in STAT_ROLLING for p in STAT_P for k in STAT_KN_G]


def stat_cases():
    """(name, kn_g, P, rolling, seed) of every run of the statistics."""
    return [(stat_name(k, p, r, s), k, p, r, s) for _, k, p, r in stat_groups() for s in range(1, STAT_SEEDS + 1)]


def stat_case(name):
    for c in stat_cases():
        if c[0] == name:
            return c
    return None


def usable_radius(cavity, radius=2.5):
    """The radius of the disc the grains fill: the cavity's less the boundary particles' bulge,
    R cos(pi/m) - R sin(pi/m) with m cavity elements."""
    return radius * (math.cos(math.pi / cavity) - math.sin(math.pi / cavity))


def stat_r0(n=None, cavity=None):
    """The mean radius of the statistics' grains (n grains, default STAT_N, in a cavity of `cavity`
    elements, default STAT_CAVITY): phi pi R_u^2 = n pi E[r^2], r uniform in [0.75, 1.25] r0."""
    usable = usable_radius(cavity or STAT_CAVITY)
    return math.sqrt(BASE["phi"] * usable**2 / ((n or STAT_N) * (1 + 0.25**2 / 3)))


def stat_rolling(kn_g, r0=None):
    """{kr, eta}: kr = kt R*^2 (beta = 1, docs/scene.md), R* = r0 / 2 between two mean grains
    (r0: default the statistics' stat_r0())."""
    kt = KT_KN * kn_g * G
    return {"kr": g6(kt * ((r0 or stat_r0()) / 2)**2), "eta": STAT_ETA}


def stat_solver():
    """The statistics' solver: global, a = STAT_A_REL x each step's mean normal contact force."""
    return {"method": "global", "accuracy": {"relative": STAT_A_REL}, "max_iterations": 3000}


def stat_like_scene(name, case, mesh, n, cavity, steps, follow=None):
    """A statistics case's scene (case: stat_case's tuple) for n grains, cavity elements and steps
    of the top; follow: the host rebased after every `follow` steps (host.updated_lagrangian)."""
    _, kn_g, p, rolling, seed = case
    dp = p / STEPS_P
    s = case_scene(name, kn_g * G, BASE["friction"], mesh, cavity, NU, "displacement", 1.0, 3000, dp, None,
                   steps, [0, -STAT_DU])
    s.solver = stat_solver()
    if rolling:
        s.materials["grain_grain"]["rolling"] = stat_rolling(kn_g, stat_r0(n, cavity))
    if follow:
        s.host["updated_lagrangian"] = {"every": follow}
    s.output = {"contacts_every": 1}   # the grains' rotations and the contact forces (Love-Weber stress)
    return s


def stat_scene(name, mesh):
    case = stat_case(name)
    return stat_like_scene(name, case, mesh, STAT_N, STAT_CAVITY, STAT_STEPS[case[1]])


# The study at scale: zones 110 grain diameters across (1e4 grains; 384 cavity elements keep the
# boundary particles' size to the grains'), the host following its deformed boundary (rebased
# after every step), the top pushed SCALE_STEPS x 0.01 cm (the zone to about 10 % of vertical
# strain); the statistics' cases at P = 100 kgf/cm^2, SCALE_SEEDS packings each (six: at least five
# per case run through, as one packing's first relaxation stalls, README "At scale"). Names
# scale/<statistics name>.
SCALE_N, SCALE_CAVITY, SCALE_SEEDS, SCALE_STEPS, SCALE_FOLLOW, SCALE_P = 10000, 384, 6, 60, 1, [100.0]


def scale_cases():
    """(name, kn_g, P, rolling, seed) of every run of the study at scale."""
    return [("scale/" + stat_name(k, p, r, s), k, p, r, s) for r in STAT_ROLLING for p in SCALE_P for k in STAT_KN_G
            for s in range(1, SCALE_SEEDS + 1)]


def scale_case(name):
    return next((c for c in scale_cases() if c[0] == name), None)


def scale_scene(name, mesh):
    s = stat_like_scene(name, scale_case(name), mesh, SCALE_N, SCALE_CAVITY, SCALE_STEPS, SCALE_FOLLOW)
    s.output["measures_every"] = 1   # the grains and host fields of every step (off by default from 5 000 grains)
    return s


def write_scene(name, path, mesh, refine=1):
    """Writes the case's scene to PATH, with its comment."""
    return scene(name, mesh, refine).write(path, comment=scene_comment(name))


def write_pack_scene(name, path, mesh):
    """Writes the case's pack scene to PATH, with its comment."""
    s, comment = pack_scene(name, mesh)
    return s.write(path, comment=comment)


def main():
    if sys.argv[1] == "cases":
        for n, phi, friction, kn in cases():
            print(n, phi, friction, kn)
    elif sys.argv[1] == "extended":
        for n, c in extended():
            print(n, c["load"], c["n"], c["kn_g"], c["nu"], c["P"])
    elif sys.argv[1] == "pack":
        print(pack_args(sys.argv[2]))
    elif sys.argv[1] == "pack_scene":
        s, comment = pack_scene(sys.argv[2], sys.argv[3])
        print(s.to_yaml(comment=comment), end="")
    elif sys.argv[1] == "scene":
        refine = int(sys.argv[5]) if len(sys.argv) > 5 else 1
        write_scene(sys.argv[2], f"{sys.argv[3]}/scene{'' if refine == 1 else f'_refine{refine}'}.yaml", sys.argv[4],
                    refine)
    elif sys.argv[1] == "disc_moduli":
        for n, g, nu in disc_moduli():
            print(n, f"{g:.6g}", f"{nu:.6g}")
    elif sys.argv[1] == "load":
        print(P, STEPS_P, DUY * STEPS, STEPS)


if __name__ == "__main__":
    main()
