#!/usr/bin/python3
"""LAMMPS side of the peer benchmark (tools/bench_peer.sh): writes LAMMPS's input for a gembem
packing, and turns LAMMPS's final dumps into a gembem-like run directory that
tools/check_equilibrium.py checks like any gembem state.

    tools/lammps_peer.py input PACKING.csv BOX.yaml OUT_DIR [--dt-factor 0.2] [--zeta-n 0.5]
                         [--tangential-damping 1] [--viscous 0.01] [--accuracy 100]
                         [--max-steps 10000000] [--path-strain E --path-steps S] [--restart FILE]
    tools/lammps_peer.py shear START_DIR OUT_DIR --steps S [--strain 0.05] [--points 20]
                         [--seed 1] [--start-velocity 0.01]
    tools/lammps_peer.py state OUT_DIR          (after `lmp -in OUT_DIR/in.relax` ran in OUT_DIR)
    tools/lammps_peer.py lawcheck OUT_DIR       (two-disc check of LAMMPS's contact law; runs lmp)

The model (one to one with gembem's, docs/method.md section 3; cgs units):
  - 2D discs (`dimension 2`, `atom_style sphere`, `fix nve/sphere disc`: inertia m r^2 / 2),
    mass per unit depth rho pi r^2 (`set density/disc`, rho = 2.65 g/cm^3; read_data alone would
    give 4/3 pi r^3 rho, a sphere's). Masses only matter for the dynamics, not the static state.
  - `pair_style gran/hooke/history kn kt gamman gammat xmu dampflag limit_damping`: normal force
    kn * overlap (LAMMPS's ccel * r = kn (r_i + r_j - |x_ij|)), the same kn = 1e8 dyn/cm;
    tangential force kt times the shear displacement, an incremental spring on the relative
    tangential velocity at the contact (translation and r_i w_i + r_j w_j, the same kinematics as
    K 1-2, 25), reset when the contact opens, capped at xmu |normal force| (K 13): kt = 7e7 dyn/cm,
    xmu = tan 25 deg. gamman: normal contact damping (force meff gamman v_n), given here as the
    fraction zeta_n of critical damping for two of the smallest discs (gamman = 2 zeta_n
    sqrt(kn / meff), meff = m_min / 2); tangential damping (dampflag 1) gammat = gamman / 2.
    limit_damping: the damping never makes a normal force attractive.
  - Walls: `fix wall/gran hooke kn 0 gamman 0 0 0` on xplane and yplane at the box's walls:
    normal force kn * overlap, xmu = 0: frictionless, as gembem's grain-wall material.
  - Global damping: `fix viscous` with a per-type scale making the drag proportional to the
    mass: F = -G omega0 m v, omega0 = sqrt(kn / m_min) (G = --viscous; types are the distinct
    radii). It damps translations only (LAMMPS 2021 has no rotational viscous fix; rotations are
    damped by the tangential contact damping).
  - Time step dt = F sqrt(m_min / kn) (--dt-factor).
  - Stopping: a `fix halt` heuristic every 50 steps (every disc's |(fx, fy, tz / r)| < A, forces
    as integrated with fix viscous's drag added back, the contact damping in), then velocities
    and spins zeroed and `run 0`: the static forces alone; if a disc's is still above A, the
    run goes on (a loop; --max-steps caps it).
    The dumps of that last `run 0` (positions, and per contact the tangential force that
    gran/hooke/history's single() returns: `compute pair/local p1 p2`, with velocities zero so no
    damping term) are what the independent checker reads.
  - A loading path (--path-strain E, the benchmark's oedometric compression; PACKING.csv and
    BOX.yaml then a gembem state's state_grains.csv and state.yaml, an equilibrium both codes
    start from): the bottom and top walls are planes (`fix wall/gran/region` on `region plane`,
    the same law as the side walls) that move towards each other at a constant velocity, each by
    E/2 of the height in S time steps (--path-steps), as gembem's `strain: {de1}` moves both
    by de1/2 of the first height; the side walls stay. Then the walls stop and the relaxation
    above runs, to the same static criterion, from the state the loading left. The walls' forces
    on the discs (their `contacts` arrays) are written at every 1/20 of the loading to
    curve.txt: step, strain, s1 = (|F_bottom| + |F_top|) / (2 width), s2 = (|F_left| + |F_right|)
    / (2 height) [dyn/cm], the stress path that gembem's 20 load steps give at rest.
  - --restart FILE: the relaxation ends with `write_restart FILE` (in OUT_DIR): positions and
    every contact's shear history (gran/hooke/history's fix NEIGH_HISTORY is in restart files),
    the start of a shear run.
  - The constant-volume biaxial shear (`shear`: START_DIR a relaxation run with --restart
    start.restart): read_restart, global drag off (no `fix viscous`; the contact damping stays),
    then the four walls move at a constant velocity for S time steps (--steps): the bottom and
    top in by e1/2 of the start height each, the sides out by e1/2 of the start width each
    (e2 = -e1, as gembem's `strain: {de1: e1/n, de2: -e1/n}` over n steps), to e1 = --strain.
    The discs start with a random velocity, each component normal with a standard deviation
    --start-velocity times the top wall's speed (seeded by --seed: a repeat with another seed is
    another trajectory of the same chaotic path). The walls' stresses are read statically: kn
    times the overlaps of the discs with each wall (the springs alone, without the contact
    damping), per current length of wall, at every S / --points steps (curve.txt: step, e1, e2,
    s1, s2, compression positive; step 0 is the start at rest).
What differs from gembem's law, invisible at rest: LAMMPS keeps the shear displacement as a
vector and, when the contact normal turns by dtheta in a step, projects it on the new tangent (its
length falls by 1 - cos dtheta; gembem's pt is a scalar turning with the contact); its Coulomb cap
uses the normal force with its damping term; its damping forces vanish with the velocities.
"""
import argparse
import math
import os
import subprocess
import sys

import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
import gembem  # noqa: E402
from gembem.yamlfile import dump_yaml  # noqa: E402

KN0, KT0, PHI_DEG, RHO = 1.0e8, 7.0e7, 25.0, 2.65


def read_packing(path):
    g = gembem.read_csv(path)
    return list(zip(*(g[k].astype(float).tolist() for k in ("x", "y", "r"))))


def read_box(path):
    with open(path) as f:
        for line in f:
            if line.startswith("box:"):
                return yaml.safe_load(line)["box"]
    sys.exit(f"lammps_peer: no 'box:' line in {path}")


def write_input(a):
    # --kn-scale s: kn and kt times s (the same packing, forces s times larger: the accuracy too)
    KN, KT = a.kn_scale * KN0, a.kn_scale * KT0
    grains = read_packing(a.packing)
    box = read_box(a.box)
    os.makedirs(a.out, exist_ok=True)
    radii = sorted({r for _, _, r in grains})
    rmin = radii[0]
    m_min = RHO * math.pi * rmin * rmin
    omega0 = math.sqrt(KN / m_min)
    dt = a.dt_factor * math.sqrt(m_min / KN)
    gamman = 2.0 * a.zeta_n * math.sqrt(KN / (m_min / 2.0))
    xmu = math.tan(math.radians(PHI_DEG))
    margin = 2.0 * radii[-1]
    # a path: each of the bottom and top walls moves in by dy_max (E/2 of the height)
    dy_max = 0.5 * a.path_strain * (box["top"] - box["bottom"])
    types = {r: k + 1 for k, r in enumerate(radii)}
    with open(os.path.join(a.out, "data.lmp"), "w") as f:
        f.write(f"gembem packing {os.path.abspath(a.packing)} for LAMMPS (tools/lammps_peer.py)\n\n")
        f.write(f"{len(grains)} atoms\n{len(radii)} atom types\n\n")
        f.write(f"{box['left'] - margin:.17g} {box['right'] + margin:.17g} xlo xhi\n")
        f.write(f"{box['bottom'] - margin:.17g} {box['top'] + margin:.17g} ylo yhi\n")
        f.write("-0.5 0.5 zlo zhi\n\nAtoms # sphere\n\n")
        for k, (x, y, r) in enumerate(grains):
            # id type diameter density x y z (the density is reset per area below)
            f.write(f"{k + 1} {types[r]} {2 * r:.17g} {RHO} {x:.17g} {y:.17g} 0\n")
    scale = " ".join(f"scale {types[r]} {(r / rmin) ** 2:.17g}" for r in radii)
    viscous = (f"fix damp all viscous {a.viscous * omega0 * m_min:.17g} {scale}"
               if a.viscous > 0 else "# no global damping")
    inp = f"""# Written by tools/lammps_peer.py for tools/bench_peer.sh: relax a gembem packing with
# LAMMPS to the static criterion (every disc's |(fx, fy, tz/r)| <= {a.accuracy:g} dyn, velocities zero).
# dt factor {a.dt_factor:g} (dt = {dt:.6g} s), zeta_n {a.zeta_n:g} (gamman = {gamman:.6g} 1/s),
# tangential damping {a.tangential_damping}, viscous {a.viscous:g} omega0 m (omega0 = {omega0:.6g} 1/s)
units           cgs
dimension       2
atom_style      sphere
boundary        f f p
comm_modify     vel yes
read_data       data.lmp
set             group all density/disc {RHO}
neighbor        {0.1 * rmin:.6g} bin
neigh_modify    delay 0 every 1 check yes
pair_style      gran/hooke/history {KN:.17g} {KT:.17g} {gamman:.17g} {"NULL" if a.tangential_damping else "0"} {xmu:.17g} {a.tangential_damping} limit_damping
pair_coeff      * *
{walls(a, box, KN, gamman, dy_max)}
fix             move all nve/sphere disc
fix             plane all enforce2d
{viscous}
timestep        {dt:.17g}

# The largest force on a disc, as gembem's fixing force: |(fx, fy, tz / r)|.
compute         pa all property/atom tqz radius
# In the run (the halt heuristic) fix viscous's drag -g m v is added back: overdamped discs would
# otherwise look balanced; after the quench (v = 0) this is the static force exactly.
variable        fex atom fx+{a.viscous * omega0:.17g}*mass*vx
variable        fey atom fy+{a.viscous * omega0:.17g}*mass*vy
variable        fres atom sqrt(v_fex*v_fex+v_fey*v_fey+(c_pa[1]/c_pa[2])^2)
compute         fmax all reduce max v_fres
variable        fmax equal c_fmax
thermo_style    custom step time ke c_fmax
thermo          10000
thermo_modify   norm no flush yes
{load(a, box)}fix             halt all halt 50 v_fmax < {a.accuracy:.17g} error continue

variable        quench loop 100000
label           relax
run             {a.max_steps} upto
velocity        all set 0.0 0.0 0.0
set             group all omega 0.0 0.0 0.0
run             0
print           "static check: step $(step) largest force $(c_fmax:%.6g) dyn"
if              "$(c_fmax) <= {a.accuracy:.17g} || $(step) >= {a.max_steps}" then "jump SELF done"
next            quench
jump            SELF relax
label           done

# The final state, velocities zero: positions, and every contact's forces on its first atom
# (pair/local force: the normal force, ccel r; p1, p2: the tangential force on the first atom).
compute         pl all pair/local dist force p1 p2 cutoff radius
compute         pp all property/local patom1 patom2 cutoff radius
dump            grains all custom 1 grains.dump id radius x y
dump_modify     grains sort id format float %.17g
dump            contacts all local 1 contacts.dump c_pp[1] c_pp[2] c_pl[1] c_pl[2] c_pl[3] c_pl[4]
dump_modify     contacts format float %.17g
unfix           halt
run             0
print           "final: step $(step) largest force $(c_fmax:%.6g) dyn"
{f"write_restart   {a.restart}" if a.restart else ""}
"""
    with open(os.path.join(a.out, "in.relax"), "w") as f:
        f.write(inp)
    with open(os.path.join(a.out, "params.yaml"), "w") as f:
        yaml.safe_dump({"packing": os.path.abspath(a.packing), "box": box, "kn": KN, "kt": KT,
                        "friction_deg": PHI_DEG, "accuracy": a.accuracy, "dt": dt,
                        "dt_factor": a.dt_factor, "zeta_n": a.zeta_n, "gamman": gamman,
                        "tangential_damping": a.tangential_damping, "viscous": a.viscous,
                        "density": RHO, "max_steps": a.max_steps, "path_strain": a.path_strain,
                        "path_steps": a.path_steps, "path_wall_move": dy_max, "restart": a.restart,
                        "rmin": rmin, "rmax": radii[-1]}, f, sort_keys=False)


def walls(a, box, kn, gamman, dy_max):
    """The four walls: fixed planes; for a path the bottom and top are planes that move in by dy_max at a
    constant velocity over --path-steps steps (`region ... move`: LAMMPS gives the wall the
    region's velocity, which the contact damping sees)."""
    law = f"hooke {kn:.17g} 0 {gamman:.17g} 0 0 0"
    if a.path_strain == 0:
        return (f"fix             walls_x all wall/gran {law} xplane {box['left']:.17g} {box['right']:.17g}\n"
                f"fix             walls_y all wall/gran {law} yplane {box['bottom']:.17g} {box['top']:.17g}")
    return f"""variable        dy equal {dy_max:.17g}*(step<{a.path_steps})*step/{a.path_steps}+{dy_max:.17g}*(step>={a.path_steps})
variable        mdy equal -v_dy
region          bottom plane 0 {box['bottom']:.17g} 0 0 1 0 side in move NULL v_dy NULL units box
region          top plane 0 {box['top']:.17g} 0 0 -1 0 side in move NULL v_mdy NULL units box
fix             walls_x all wall/gran {law} xplane {box['left']:.17g} {box['right']:.17g} contacts
fix             wall_bottom all wall/gran/region {law} region bottom contacts
fix             wall_top all wall/gran/region {law} region top contacts"""


def load(a, box):
    """The loading of a path: the walls' move, before the relaxation."""
    if a.path_strain == 0:
        return ""
    width, height = box["right"] - box["left"], box["top"] - box["bottom"]
    every = a.path_steps // 20
    return f"""# The loading: the walls move in at a constant velocity for {a.path_steps} steps, then stop;
# the walls' forces on the discs (columns 2 and 3 of a wall's contacts array: fx, fy) every 1/20 of it.
variable        fxabs atom abs(f_walls_x[2])
compute         wx all reduce sum v_fxabs
compute         wb all reduce sum f_wall_bottom[3]
compute         wt all reduce sum f_wall_top[3]
variable        e1 equal 2*v_dy/{height:.17g}
variable        s1 equal (abs(c_wb)+abs(c_wt))/(2*{width:.17g})
variable        s2 equal c_wx/(2*({height:.17g}-2*v_dy))
fix             curve all print {every} "$(step) $(v_e1:%.10g) $(v_s1:%.10g) $(v_s2:%.10g)" file curve.txt screen no title "step e1 s1 s2"
run             {a.path_steps}
unfix           curve
print           "loaded: step $(step) largest force $(c_fmax:%.6g) dyn"
"""


def write_shear(a):
    """OUT_DIR/in.shear: the constant-volume biaxial shear from START_DIR's restart (module doc)."""
    p = yaml.safe_load(open(os.path.join(a.start, "params.yaml")))
    if not p.get("restart") or float(p.get("path_wall_move", 0)) != 0:
        sys.exit(f"lammps_peer: {a.start} is not a relaxation written with --restart")
    restart = os.path.abspath(os.path.join(a.start, p["restart"]))
    box = {k: float(p["box"][k]) for k in ("left", "right", "bottom", "top")}
    width, height = box["right"] - box["left"], box["top"] - box["bottom"]
    kn, dt, rmin, rmax = float(p["kn"]), float(p["dt"]), float(p["rmin"]), float(p["rmax"])
    dy_max, dx_max = 0.5 * a.strain * height, 0.5 * a.strain * width  # each wall's move
    v0 = a.start_velocity * dy_max / (a.steps * dt)
    law = f"hooke {kn:.17g} 0 {float(p['gamman']):.17g} 0 0 0"
    # a wall's spring force on each disc: kn times its overlap (the wall at coordinate c, the
    # disc's distance to it d: max(r - d, 0)); the contact damping is left out
    ov = lambda d: f"(c_radius-({d}))*(c_radius>({d}))"
    os.makedirs(a.out, exist_ok=True)
    inp = f"""# Written by tools/lammps_peer.py shear for tools/bench_peer.sh: the constant-volume biaxial
# shear to e1 = {a.strain:g} (e2 = -e1) in {a.steps} time steps from the relaxation {a.start}.
units           cgs
read_restart    {restart}
comm_modify     vel yes
neighbor        {0.1 * rmin:.6g} bin
neigh_modify    delay 0 every 1 check yes
# a run of no step first: the contacts' shear history comes back from the restart file with it
# (change_box refuses a box with per-atom restart data not yet taken up)
run             0
# room for the side walls' move out (the box's boundaries are fixed: a disc beyond them is lost)
change_box      all x final {box['left'] - 2 * rmax - dx_max:.17g} {box['right'] + 2 * rmax + dx_max:.17g} units box
reset_timestep  0
# the walls' moves: bottom and top in by dy, the sides out by dx, linear in time (constant velocity)
variable        dy equal {dy_max:.17g}*step/{a.steps}
variable        dx equal {dx_max:.17g}*step/{a.steps}
variable        mdy equal -v_dy
variable        mdx equal -v_dx
region          bottom plane 0 {box['bottom']:.17g} 0 0 1 0 side in move NULL v_dy NULL units box
region          top plane 0 {box['top']:.17g} 0 0 -1 0 side in move NULL v_mdy NULL units box
region          left plane {box['left']:.17g} 0 0 1 0 0 side in move v_mdx NULL NULL units box
region          right plane {box['right']:.17g} 0 0 -1 0 0 side in move v_dx NULL NULL units box
fix             wall_bottom all wall/gran/region {law} region bottom
fix             wall_top all wall/gran/region {law} region top
fix             wall_left all wall/gran/region {law} region left
fix             wall_right all wall/gran/region {law} region right
fix             move all nve/sphere disc
fix             plane all enforce2d
# no fix viscous: global damping off while loading
timestep        {dt:.17g}
# the start velocities: normal, standard deviation {a.start_velocity:g} of the top wall's speed, seed {a.seed}
variable        vx0 atom normal(0,{v0:.17g},{a.seed})
variable        vy0 atom normal(0,{v0:.17g},{a.seed + 104729})
velocity        all set v_vx0 v_vy0 NULL units box
# the walls' stresses from their springs alone (kn times the overlaps), per current length of wall
compute         radius all property/atom radius
variable        ob atom {ov(f"y-({box['bottom']:.17g}+v_dy)")}
variable        ot atom {ov(f"({box['top']:.17g}-v_dy)-y")}
variable        ol atom {ov(f"x-({box['left']:.17g}-v_dx)")}
variable        or atom {ov(f"({box['right']:.17g}+v_dx)-x")}
compute         ob all reduce sum v_ob
compute         ot all reduce sum v_ot
compute         ol all reduce sum v_ol
compute         or all reduce sum v_or
variable        e1 equal 2*v_dy/{height:.17g}
variable        e2 equal -2*v_dx/{width:.17g}
variable        s1 equal {kn:.17g}*(c_ob+c_ot)/(2*({width:.17g}+2*v_dx))
variable        s2 equal {kn:.17g}*(c_ol+c_or)/(2*({height:.17g}-2*v_dy))
fix             curve all print {a.steps // a.points} "$(step) $(v_e1:%.10g) $(v_e2:%.10g) $(v_s1:%.10g) $(v_s2:%.10g)" file curve.txt screen no title "step e1 e2 s1 s2"
thermo_style    custom step ke
thermo          {max(a.steps // 10, 1)}
thermo_modify   norm no flush yes
run             {a.steps}
print           "sheared: step $(step) e1 $(v_e1:%.10g)"
"""
    with open(os.path.join(a.out, "in.shear"), "w") as f:
        f.write(inp)
    with open(os.path.join(a.out, "params.yaml"), "w") as f:
        yaml.safe_dump({"start": os.path.abspath(a.start), "strain": a.strain, "steps": a.steps,
                        "points": a.points, "seed": a.seed, "start_velocity": a.start_velocity,
                        "start_velocity_std": v0, "dt": dt, "kn": kn}, f, sort_keys=False)


def read_dump(path):
    """The last snapshot of a LAMMPS dump: its column names and rows of floats."""
    cols, rows, reading = None, [], False
    with open(path) as f:
        for line in f:
            if line.startswith("ITEM:"):
                reading = line.startswith("ITEM: ATOMS") or line.startswith("ITEM: ENTRIES")
                if reading:
                    cols, rows = line.split()[2:], []
                continue
            if reading:
                rows.append([float(v) for v in line.split()])
    if cols is None:
        sys.exit(f"lammps_peer: no snapshot in {path}")
    return cols, rows


def write_state(a):
    """A gembem-like run directory OUT_DIR/state from LAMMPS's final dumps: scene.yaml (the
    materials and accuracy), state.yaml (the box), state_grains.csv (x, y, r in LAMMPS's final
    positions) and state_contacts.csv (i, j, pn, pt: pn from LAMMPS's normal force, pt from its
    tangential force in gembem's sign convention)."""
    p = yaml.safe_load(open(os.path.join(a.out, "params.yaml")))
    _, gr = read_dump(os.path.join(a.out, "grains.dump"))
    _, ct = read_dump(os.path.join(a.out, "contacts.dump"))
    pos = {int(r[0]): (r[2], r[3], r[1]) for r in gr}
    n = len(pos)
    if sorted(pos) != list(range(1, n + 1)):
        sys.exit("lammps_peer: atoms lost or renumbered in grains.dump")
    d = os.path.join(a.out, "state")
    os.makedirs(d, exist_ok=True)
    gembem.write_grains_csv(os.path.join(d, "state_grains.csv"), [pos[k] for k in range(1, n + 1)])
    seen = set()
    with open(os.path.join(d, "state_contacts.csv"), "w") as f:
        f.write("i,j,pn,pt\n")
        for a1, a2, dist, fnorm, fs1, fs2 in ct:
            a1, a2 = int(a1), int(a2)
            if a1 > a2:  # gembem stores i < j; the force on the other atom is the opposite
                a1, a2, fs1, fs2 = a2, a1, -fs1, -fs2
            if (a1, a2) in seen:
                continue  # a pair listed twice (ghost images): not expected with walls
            seen.add((a1, a2))
            (xi, yi, _), (xj, yj, _) = pos[a1], pos[a2]
            nx, ny = (xj - xi) / dist, (yj - yi) / dist  # normal from i to j
            # pair/local's force is ccel r, the normal force (positive: repulsive). LAMMPS's
            # force on i: -(ccel r) n + fs; gembem's P on i is -(pn n + pt t), t = (-ny, nx):
            # pn = ccel r, pt = -fs.t
            pn = fnorm
            pt = -(fs1 * -ny + fs2 * nx)
            f.write(f"{a1 - 1},{a2 - 1},{pn:.17g},{pt:.17g}\n")
    box = {k: float(p["box"][k]) for k in ("left", "right", "bottom", "top")}
    move = float(p.get("path_wall_move", 0))  # a path's walls ended there
    box["bottom"] += move
    box["top"] -= move
    with open(os.path.join(d, "state.yaml"), "w") as f:
        f.write("# LAMMPS's final state, written by tools/lammps_peer.py state\n")
        f.write(dump_yaml({"gembem_state": 1, "box": box,
                           "grains": {"file": "state_grains.csv", "contacts": "state_contacts.csv"}}))
    kn, kt = float(p["kn"]), float(p["kt"])
    gembem.Scene(units={"length": "cm", "force": "dyn"},
                 materials={"grain_grain": {"kn": kn, "kt": kt, "friction_deg": float(f"{p['friction_deg']:g}")},
                            "grain_wall": {"kn": kn, "kt": kt, "friction_deg": 0}},
                 solver={"method": "global", "accuracy": float(p["accuracy"])}).write(
        os.path.join(d, "scene.yaml"), comment="The materials of LAMMPS's run, for tools/check_equilibrium.py")
    print(d)


def lawcheck(a):
    """Two discs, LAMMPS's contact law against gembem's (docs/method.md K 3, 6, 13), no damping:
    disc 2 (r 0.45) at the origin with no integrator (it does not move), disc 1 (r 0.3) above it
    at an overlap d = 1e-4 cm, moved by `fix move` only: slid along the tangent by u1 = 2e-5 cm,
    then spun about its centre by w = 3e-5 cm / r1, then slid by 1e-3 cm more (it slides). In
    gembem's convention (contact from disc 1 to disc 2, n = (0, -1), t = (-ny, nx) = (1, 0)) the
    expected forces are pn = kn d (from the dumped distance), pt = kt u1, then kt (u1 + r1 w) (the
    incremental spring of K 6 on du_t = dx.t + r dw), then xmu pn (K 13). Prints each stage and
    exits 1 if a force is off by more than 1e-4 of kt u1 (the contact normal turns by u / (r1 +
    r2) = 3e-5 rad as disc 1 slides: LAMMPS projects its shear vector onto the new tangent
    plane, an increment of order (u / (r1 + r2))^2 of the force)."""
    os.makedirs(a.out, exist_ok=True)
    r1, r2, d = 0.3, 0.45, 1e-4
    y1 = r1 + r2 - d
    xmu = math.tan(math.radians(PHI_DEG))
    dt, nsteps = 1e-6, 100
    u1, w, u3 = 2e-5, 3e-5 / r1, 1e-3
    vel = lambda u: u / (nsteps * dt)
    period = 2 * math.pi * nsteps * dt / w  # fix move rotate: angle w in nsteps steps
    inp = f"""# Written by tools/lammps_peer.py lawcheck: LAMMPS's contact law on two discs
units           cgs
dimension       2
atom_style      sphere
boundary        f f p
comm_modify     vel yes
region          box block -2 2 -2 2 -0.5 0.5
create_box      1 box
create_atoms    1 single 0 {y1:.17g} 0
create_atoms    1 single 0 0 0
set             atom 1 diameter {2 * r1}
set             atom 2 diameter {2 * r2}
set             group all density/disc {RHO}
pair_style      gran/hooke/history {KN0:.17g} {KT0:.17g} 0 0 {xmu:.17g} 0
pair_coeff      * *
neighbor        0.1 bin
timestep        {dt}
group           one id 1
compute         pl all pair/local dist force p1 p2 cutoff radius
compute         pp all property/local patom1 patom2 cutoff radius
dump            c all local {nsteps} law.dump c_pp[1] c_pp[2] c_pl[1] c_pl[2] c_pl[3] c_pl[4]
dump_modify     c format float %.17g
fix             m one move linear {vel(u1):.17g} 0 0
run             {nsteps}
unfix           m
fix             m one move rotate {u1:.17g} {y1:.17g} 0 0 0 1 {period:.17g}
run             {nsteps}
unfix           m
fix             m one move linear {vel(u3):.17g} 0 0
run             {nsteps}
"""
    with open(os.path.join(a.out, "in.law"), "w") as f:
        f.write(inp)
    subprocess.run(["lmp", "-in", "in.law", "-log", "law.log", "-screen", "none"], cwd=a.out,
                   check=True)
    snaps, reading = [], False
    with open(os.path.join(a.out, "law.dump")) as f:
        for line in f:
            if line.startswith("ITEM:"):
                reading = line.startswith("ITEM: ENTRIES")
                if reading:
                    snaps.append([])
                continue
            if reading:
                snaps[-1].append([float(v) for v in line.split()])
    if len(snaps) != 4 or any(len(s) != 1 for s in snaps):
        sys.exit("lammps_peer lawcheck: expected 4 snapshots of one contact in law.dump")
    worst, scale = 0.0, KT0 * u1
    labels = ["pressed", f"slid by u1 = {u1:g}", f"spun by r1 w = {r1 * w:g}", f"slid by {u3:g} more"]
    expect_pt = [0.0, KT0 * u1, KT0 * (u1 + r1 * w), None]
    for k, (snap, lab) in enumerate(zip(snaps, labels)):
        p1, p2, dist, fnorm, fs1, fs2 = snap[0]
        if int(p1) != 1:  # the force on disc 1
            fs1, fs2 = -fs1, -fs2
        pn_expect = KN0 * (r1 + r2 - dist)
        x1 = [0.0, u1, u1, u1 + u3][k]  # disc 1's centre (x1, y1), prescribed by fix move
        nx, ny = -x1 / dist, -y1 / dist  # from disc 1 to disc 2 (at the origin)
        pt = -(fs1 * -ny + fs2 * nx)  # the tangential force on disc 1 is -pt t, t = (-ny, nx)
        pt_expect = expect_pt[k] if expect_pt[k] is not None else xmu * pn_expect
        err = max(abs(fnorm - pn_expect), abs(pt - pt_expect)) / scale
        worst = max(worst, err)
        print(f"  {lab}: LAMMPS pn {fnorm:.8g}, pt {pt:.8g}; gembem's law pn {pn_expect:.8g}, "
              f"pt {pt_expect:.8g} dyn")
    print(f"lawcheck: largest difference {worst:.2g} of kt u1 ({scale:g} dyn)")
    return 0 if worst <= 1e-4 else 1


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    p = sub.add_parser("input")
    p.add_argument("packing")
    p.add_argument("box")
    p.add_argument("out")
    p.add_argument("--dt-factor", type=float, default=0.2)
    p.add_argument("--zeta-n", type=float, default=0.5)
    p.add_argument("--tangential-damping", type=int, choices=(0, 1), default=1)
    p.add_argument("--viscous", type=float, default=0.01)
    p.add_argument("--accuracy", type=float, default=100.0)
    p.add_argument("--max-steps", type=int, default=10000000)
    p.add_argument("--kn-scale", type=float, default=1.0)
    p.add_argument("--path-strain", type=float, default=0.0,
                   help="a loading path: the walls' total vertical strain (0: a relaxation)")
    p.add_argument("--path-steps", type=int, default=50000,
                   help="the time steps over which the walls move (the loading rate)")
    p.add_argument("--restart", default="", help="write_restart this file (in OUT_DIR) at the end")
    p = sub.add_parser("shear")
    p.add_argument("start", help="a relaxation's OUT_DIR, written with --restart")
    p.add_argument("out")
    p.add_argument("--steps", type=int, required=True, help="the time steps of the whole shear")
    p.add_argument("--strain", type=float, default=0.05, help="e1 at the end (e2 = -e1)")
    p.add_argument("--points", type=int, default=20, help="curve.txt's points past the start")
    p.add_argument("--seed", type=int, default=1, help="the start velocities' seed")
    p.add_argument("--start-velocity", type=float, default=0.01,
                   help="the start velocities' standard deviation over the top wall's speed")
    p = sub.add_parser("state")
    p.add_argument("out")
    p = sub.add_parser("lawcheck")
    p.add_argument("out")
    a = ap.parse_args()
    if a.cmd == "input":
        if a.path_strain and (a.path_steps < 20 or a.path_steps % 20):
            sys.exit("lammps_peer: --path-steps must be a positive multiple of 20 (the curve's points)")
        write_input(a)
    elif a.cmd == "shear":
        if a.points < 1 or a.steps < a.points or a.steps % a.points:
            sys.exit("lammps_peer: --steps must be a positive multiple of --points")
        if not 0 < a.strain < 0.5 or a.seed < 1 or a.start_velocity < 0:
            sys.exit("lammps_peer: --strain must be in (0, 0.5), --seed >= 1, --start-velocity >= 0")
        write_shear(a)
    elif a.cmd == "state":
        write_state(a)
    else:
        sys.exit(lawcheck(a))


if __name__ == "__main__":
    main()
