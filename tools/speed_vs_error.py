#!/usr/bin/python3
"""Speed against error (a benchmark, not a test), in parts, each a section of
validation/SPEED_VS_ERROR.md with its own PNG:

  three_discs  the three-disc shear test of Kishino (1989) run over kn, the accuracy a, alpha and
               the solver; the error is the largest distance of the stress ratio from the rigid
               exact solution (docs/method.md section 7) at e1 - e2 = 1..5 %
  bem          the boundary element module: Lame's annulus and Kirsch's hole refined
               (build/speed_error_bem)
  cavity       the 27-grain hybrid cavity packing (validation/cavity_packing), confined and as
               placed, over the accuracy a and the linear solver; the error is the distance from a
               tightly converged run of the same scene
  jammed1e4    10 000 discs jammed by gembem pack (tools/jammed_packing.sh), one step of isotropic stress
               control to 1.05 x the packing's initial mean stress, over a and the solver; the error
               is the distance from a tightly converged run of the same scene

The cost is the solver's seconds (steps.csv, the sum over all steps, without start-up and output),
the fastest of a few runs.

usage: tools/speed_vs_error.py [BUILD_DIR] [--only PART[,PART...]]
--only reruns the parts named and keeps the other sections of SPEED_VS_ERROR.md as they are.
To add a part, write a function that returns its section's lines (starting with its "## " heading)
and list it in PARTS with that heading; run_scene() runs a scene and reports its run directory, seconds and
iterations.
"""
import argparse
import datetime
import math
import os
import platform
import re
import subprocess
import sys
import textwrap

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import matplotlib.ticker

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "validation", "three_discs"))
sys.path.insert(0, os.path.join(ROOT, "validation", "cavity_packing"))
sys.path.insert(0, os.path.join(ROOT, "python"))
import gembem  # noqa: E402
import numpy as np  # noqa: E402
from cavity import cavity_scene  # noqa: E402
from gembem.yamlfile import Loader  # noqa: E402
from table2 import exact_ratio  # noqa: E402
import yaml  # noqa: E402

BUILD = os.path.join(ROOT, "build")  # set by main()
RUNS = os.path.join(ROOT, "runs", "speed_vs_error")
BASE = gembem.Scene.load(os.path.join(ROOT, "validation", "three_discs", "case1.yaml"))
MD = os.path.join(ROOT, "validation", "SPEED_VS_ERROR.md")
SOLVERS = {"reference": {"method": "reference"}, "global CHOLMOD": {"method": "global", "linear": "cholmod"},
           "global UMFPACK": {"method": "global", "linear": "umfpack"}}


def save_figure(fig, name):
    """Writes a figure of the page to validation/NAME."""
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "validation", name), dpi=110)


def run_scene(name, scene, repeat=3, fast=0.1, fast_repeat=7, timeout=None):
    """Writes `scene` (a gembem.Scene) to runs/speed_vs_error/NAME/scene.yaml and runs it `repeat` times (`fast_repeat`
    times if the first run's solver took less than `fast` seconds): the machine is shared, so the
    fastest run counts. Returns (run directory, seconds, iterations, steps.csv's Table); with `timeout`
    (wall seconds per run) a run that takes longer raises subprocess.TimeoutExpired."""
    d = os.path.join(RUNS, name)
    scene.write(os.path.join(d, "scene.yaml"))
    best, n = None, 0
    while n < (repeat if best is None or best >= fast else fast_repeat):
        subprocess.run([os.path.join(BUILD, "gembem"), "run", os.path.join(d, "scene.yaml"), "-o",
                        os.path.join(d, "run"), "--overwrite", "--quiet"], check=True, timeout=timeout)
        rows = gembem.Run(os.path.join(d, "run")).steps
        secs = float(np.sum(rows["seconds"]))
        best = secs if best is None else min(best, secs)
        n += 1
    return os.path.join(d, "run"), best, int(np.sum(rows["iterations"])), rows


def run_scenes(jobs, repeat=7):
    """Runs every scene of jobs ({name: gembem.Scene}) `repeat` times, round-robin, so that a burst of load on
    the shared machine does not fall on all the runs of one setting. Returns {name: (run directory,
    the fastest run's seconds, iterations, steps.csv rows)}; the runs are deterministic."""
    best = {}
    for _ in range(repeat):
        for name, scene in jobs.items():
            d, secs, iters, rows = run_scene(name, scene, repeat=1, fast=0.0)
            if name not in best or secs < best[name][1]:
                best[name] = (d, secs, iters, rows)
    return best


def run(kn, a, alpha, solver, repeat=3):
    """Case 1 of the three discs with kn (kt = 0.7 kn), the accuracy a, alpha and the solver."""
    scene = BASE
    for m in ("grain_grain", "grain_wall"):
        scene = scene.with_value(f"materials.{m}.kn", kn).with_value(f"materials.{m}.kt", 7 * kn / 10)
    scene = scene.with_value("solver.accuracy", a).with_value("solver.alpha", alpha)
    for key, value in SOLVERS[solver].items():
        scene = scene.with_value(f"solver.{key}", value)
    name = f"kn{kn:.0e}_a{a}_alpha{alpha}_{solver.replace(' ', '_')}"
    _, best, iters, rows = run_scene(name, scene, repeat, fast=0.0)
    shear = rows.select(rows["stage"] == 2)
    err = 0.0
    for k in range(1, 6):
        at = np.abs(shear["e1_minus_e2"] - 0.01 * k) < 1e-9
        err = max([err] + [abs(v - exact_ratio(0.01 * k)) for v in shear["stress_ratio"][at]])
    return err, best, iters


def bem_section():
    """Lame and Kirsch: error against seconds as the elements are refined (one dense LU each)."""
    env = dict(os.environ, OPENBLAS_NUM_THREADS="2")
    text = subprocess.run([os.path.join(BUILD, "speed_error_bem")], cwd=ROOT, env=env, check=True,
                          capture_output=True, text=True).stdout
    rows = gembem.parse_csv(text, "speed_error_bem's output")
    fig, ax = plt.subplots(figsize=(7, 5))
    for case, mark, label in (("lame", "o-", "Lame annulus, u_r on the cavity"),
                              ("kirsch", "s-", "Kirsch, hoop stress at r = 1.5 a")):
        k = rows["case"] == case
        ax.loglog(rows["seconds"][k], rows["error"][k], mark, label=label)
    ax.set_xlabel("seconds (mesh, assembly, dense LU solve; 2 OpenBLAS threads)")
    ax.set_ylabel("relative error")
    ax.set_title("Boundary elements: error against cost, 16 to 1024 elements per circle")
    ax.legend()
    save_figure(fig, "speed_vs_error_bem.png")
    out = ["## Boundary elements: Lame and Kirsch", "", f"Measured {datetime.date.today()}.", "",
           "Lame's annulus 1 < r < 2 (inner pressure, outer fixed, plane strain, nu = 0.3): the largest",
           "relative error of u_r on the cavity; Kirsch (a hole of radius 1 in an infinite plane under",
           "s_xx = 1): the hoop stress at r = 1.5 on the vertical axis from an interior point. N elements per",
           "circle; seconds for meshing (gmsh), assembly and the dense solve, the fastest of 3 runs.", "",
           "![error against seconds](speed_vs_error_bem.png)", "",
           "| case | N | seconds | error |", "|---|---|---|---|"]
    for case, n, secs, err in zip(rows["case"], rows["N"], rows["seconds"], rows["error"]):
        out.append(f"| {case} | {n} | {secs:.4f} | {err:.2e} |")
    out += ["", "What to pick: constant elements converge at first order on the boundary (the error halves",
            "when N doubles, while the cost grows like N^2 to N^3): for 1e-3 on boundary displacements",
            "take about 400 elements per circle (0.1 s). Interior stresses half a radius away from the",
            "hole converge much faster (Kirsch: 3e-5 at 128 elements) until the interior",
            "quadrature's own tolerance, about 2e-6, takes over.", ""]
    return out


def three_discs_section():
    """Three discs: kn, a, alpha and the solver swept against the exact stress ratio."""
    rows = []
    for solver in SOLVERS:
        for kn in (1e8, 1e9, 1e10, 1e11, 1e12):
            for a in (100, 1):
                rows.append((solver, kn, a, 0.75) + run(kn, a, 0.75, solver))
    for alpha in (0.5, 0.9, 1.0):
        for kn in (1e8, 1e10, 1e12):
            rows.append(("reference", kn, 1, alpha) + run(kn, 1, alpha, "reference"))
    fig, ax = plt.subplots(figsize=(7, 5))
    for solver, mark in zip(SOLVERS, "osd"):
        pts = sorted((r[5], r[4]) for r in rows if r[0] == solver and r[3] == 0.75)
        ax.loglog([p[0] for p in pts], [max(p[1], 1e-6) for p in pts], mark + "-", label=solver)
    ax.set_xlabel("seconds (solver only, 110 load steps)")
    ax.set_ylabel("largest |stress ratio - exact| at 1..5 %")
    ax.set_title("Three discs: error against cost (kn 1e8..1e12, a = 100 and 1)")
    ax.legend()
    save_figure(fig, "speed_vs_error_three_discs.png")

    out = [
        "## Three discs (Kishino 1989, section 3)",
        "",
        f"Measured {datetime.date.today()}; the fastest of 3 runs.",
        "",
        "Error: the largest distance of the stress ratio from the rigid exact solution (docs/method.md",
        "section 7) at e1 - e2 = 1, 2, 3, 4, 5 %. kt = 0.7 kn, s0 = 1.5e5 dyn/cm, 110 load steps.",
        "",
        "![error against seconds](speed_vs_error_three_discs.png)",
        "",
        "| solver | kn [dyn/cm] | a [dyn] | alpha | error | seconds | iterations |",
        "|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        out.append(f"| {r[0]} | {r[1]:.0e} | {r[2]} | {r[3]} | {r[4]:.1e} | {r[5]:.4f} | {r[6]} |")
    out += [
        "",
        "What to pick: the error falls like 1/kn (the overlaps) until the accuracy a takes over:",
        "with a = 100 dyn the reference iteration stops about 1e-4 from the exact ratio from",
        "kn = 1e10 up, while the global solver's Newton steps land well inside a. For an error",
        "below 1e-4 take kn >= 1e10 with a = 1, or the global solver (CHOLMOD: its iterations stay",
        "near 900 from kn = 1e10 to 1e12, the reference's grow from 12 900 to 70 000); UMFPACK gives",
        "the same answers as CHOLMOD at 3-4 times its cost on these symmetric systems. Three discs",
        "take milliseconds either way: the choice matters for large packings.",
        "",
    ]
    return out


CAVITY = os.path.join(ROOT, "validation", "cavity_packing", "scene.yaml")
CAVITY_SOLVERS = {"global CHOLMOD": "cholmod", "global UMFPACK": "umfpack"}
CAVITY_ACCURACIES = (1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8)  # a [kgf]
CAVITY_TIGHT = 1e-9  # a [kgf] of the reference runs
CAVITY_REPEAT = 7  # runs of each setting; the fastest counts
FLOOR = 1e-12  # zero errors are drawn here on the log axes


def cavity_result(d):
    """Grain positions, the grains' force on each cavity element, the largest overlap, the contacts
    left, the largest fixing force of a finished run, and the grain with the largest force left
    (summed from state_contacts.csv: grain i gets -(pn n + pt t), j the opposite, t = (-ny, nx)) with
    its number of contacts."""
    run = gembem.Run(d)
    g, p, c = run.state.grains, run.host_particles, run.state.contacts
    grains = list(zip(g["x"].tolist(), g["y"].tolist()))
    forces = list(zip(p["grain_fx"].tolist(), p["grain_fy"].tolist()))
    overlap = max(c["overlap"].tolist() + [0.0])
    fix = float(run.steps["max_fixing_force"][-1])
    net, count = {}, {}
    for i, j, pn, pt, nx, ny in zip(c["i"].astype(str), c["j"].astype(str), *(c[k].tolist() for k in ("pn", "pt", "nx", "ny"))):
        f = (pn * nx - pt * ny, pn * ny + pt * nx)
        for g, sign in ((i, -1), (j, 1)):
            v = net.setdefault(g, [0.0, 0.0])
            v[0] += sign * f[0]
            v[1] += sign * f[1]
            count[g] = count.get(g, 0) + 1
    worst = max((g for g in net if not g.startswith("p")), key=lambda g: math.hypot(*net[g]), default=None)
    return {"grains": grains, "forces": forces, "overlap": max(overlap, 0.0), "contacts": c.nrows,
            "fixing": fix, "worst": worst, "worst_contacts": count.get(worst, 0)}


def position_error(r, ref):
    return max(math.hypot(a[0] - b[0], a[1] - b[1]) for a, b in zip(r["grains"], ref["grains"]))


def force_error(r, ref):
    """max over the cavity elements of |F - F_ref| / max |F_ref| (F: the grains' force on it)."""
    top = max(math.hypot(*f) for f in ref["forces"])
    return max(math.hypot(a[0] - b[0], a[1] - b[1]) for a, b in zip(r["forces"], ref["forces"])) / top


def cavity_reference_iteration():
    """Does the reference iteration run a hybrid scene? Returns None if so, else gembem's message."""
    d = os.path.join(RUNS, "cavity_reference")
    cavity_scene("confined", accuracy=1e-3, method="reference").write(os.path.join(d, "scene.yaml"))
    p = subprocess.run([os.path.join(BUILD, "gembem"), "run", os.path.join(d, "scene.yaml"), "-o",
                        os.path.join(d, "run"), "--overwrite", "--quiet"], capture_output=True, text=True)
    return None if p.returncode == 0 else p.stderr.strip().replace(d + "/", "")


def cavity_section():
    """The 27-grain cavity packing: error against a tightly converged run, over a and the solver."""
    load = os.getloadavg()
    refusal = cavity_reference_iteration()
    if refusal is None:
        sys.exit("the reference iteration now runs hybrid scenes: add it to CAVITY_SOLVERS")
    jobs = {}
    for solver, lin in CAVITY_SOLVERS.items():
        jobs[f"cavity_confined_{lin}_tight"] = cavity_scene("confined", lin, CAVITY_TIGHT)
        for case in ("confined", "placed"):
            for a in CAVITY_ACCURACIES:
                jobs[f"cavity_{case}_{lin}_a{a:g}"] = cavity_scene(case, lin, a)
    done = run_scenes(jobs, CAVITY_REPEAT)
    ref, tight = {}, {}
    for solver, lin in CAVITY_SOLVERS.items():
        d, secs, iters, _ = done[f"cavity_confined_{lin}_tight"]
        ref[solver] = cavity_result(d)
        tight[solver] = (secs, iters)
    exact = ref["global UMFPACK"]  # the exact host stiffness; CHOLMOD solves its symmetric part
    rows = {"confined": [], "placed": []}
    for case in rows:
        for solver, lin in CAVITY_SOLVERS.items():
            for a in CAVITY_ACCURACIES:
                d, secs, iters, _ = done[f"cavity_{case}_{lin}_a{a:g}"]
                r = cavity_result(d)
                if case == "confined":
                    r.update(pos=position_error(r, exact), force=force_error(r, exact),
                             own=position_error(r, ref[solver]))
                rows[case].append(dict(r, solver=solver, a=a, secs=secs, iters=iters))
    # the reference's own error: against a run 100 times tighter still (untimed)
    tighter = cavity_result(run_scene("cavity_confined_umfpack_tighter", cavity_scene(
        "confined", "umfpack", CAVITY_TIGHT / 100), repeat=1)[0])
    self_pos = position_error(exact, tighter)
    sym_pos = position_error(ref["global CHOLMOD"], exact)
    sym_force = force_error(ref["global CHOLMOD"], exact)
    # the iterations per decade of a, with friction and without (one run each end, untimed)
    lo, hi = CAVITY_ACCURACIES[0], CAVITY_ACCURACIES[-1]
    decades = math.log10(lo / hi)
    conf = {r["a"]: r for r in rows["confined"] if r["solver"] == "global UMFPACK"}
    per_decade = (conf[hi]["iters"] - conf[lo]["iters"]) / decades
    nofric = [run_scene(f"cavity_confined_frictionless_a{a:g}", cavity_scene("confined", "umfpack", a).with_value(
        "materials.grain_grain.friction_deg", 0), repeat=1)[2] for a in (lo, hi)]
    ratio = sorted(u["secs"] / c["secs"] for u, c in zip(
        [r for r in rows["confined"] if r["solver"] == "global UMFPACK"],
        [r for r in rows["confined"] if r["solver"] == "global CHOLMOD"]))[len(CAVITY_ACCURACIES) // 2]
    slope = sorted(conf[a]["pos"] / a for a in CAVITY_ACCURACIES)[len(CAVITY_ACCURACIES) // 2]
    chol = {r["a"]: r for r in rows["confined"] if r["solver"] == "global CHOLMOD"}
    same_iters = all(chol[a]["iters"] == conf[a]["iters"] for a in CAVITY_ACCURACIES)
    top = max(math.hypot(*f) for f in exact["forces"])
    asym = float(gembem.Run(done["cavity_confined_umfpack_tight"][0]).host_info["asymmetry"])
    apart = position_error(*[r for r in rows["placed"] if r["a"] == hi])

    secs = [r["secs"] for case in rows for r in rows[case]]
    xlim = (min(secs) / 1.5, max(secs) * 1.5)
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.8))
    panels = (("confined", "pos", "largest grain position error [cm]", "confined: grain positions"),
              ("confined", "force", "max |F - F_ref| / max |F_ref| on the cavity", "confined: cavity forces"),
              ("placed", "overlap", "largest overlap left [cm]", "as placed: overlap left"))
    for ax, (case, key, ylabel, title) in zip(axes, panels):
        for solver, mark in zip(CAVITY_SOLVERS, "sd"):
            pts = [(r["secs"], max(r[key], FLOOR), r["a"]) for r in rows[case] if r["solver"] == solver]
            line, = ax.loglog([p[0] for p in pts], [p[1] for p in pts], mark + "-", label=solver)
            groups = []  # consecutive a with the same error (a plateau) share one label, at its slowest run
            for x, y, a in pts:
                if groups and abs(math.log10(y / groups[-1][-1][1])) < 0.15:
                    groups[-1].append((x, y, a))
                else:
                    groups.append([(x, y, a)])
            for g in groups:
                name = "..".join(dict.fromkeys(f"{p[2]:.0e}".replace("e-0", "e-") for p in (g[0], g[-1])))
                x, y, _ = max(g)
                ax.annotate(name, (x, y), fontsize=6, color=line.get_color(), xytext=(3, 3),
                            textcoords="offset points")
        if case == "confined":
            ax.axhline(sym_pos if key == "pos" else sym_force, color="grey", ls=":",
                       label="CHOLMOD's tight run (symmetrised K)")
        if key == "pos":
            pts = [(r["secs"], max(r["own"], FLOOR)) for r in rows[case] if r["solver"] == "global CHOLMOD"]
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], "s--", color="C0", alpha=0.4, mfc="none",
                      label="CHOLMOD against its own tight run")
        ax.set_xlim(xlim)
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_xlabel("seconds (solver only)")
        ax.set_ylabel(ylabel)
        ax.set_title(title, fontsize=10)
        ax.legend(fontsize=7)
    fig.suptitle(f"Cavity packing (27 grains, 24 cavity elements): error against cost, a = 1e-1..1e-8 kgf "
                 f"(labels); errors against UMFPACK at a = {CAVITY_TIGHT:g}; below {FLOOR:g} drawn at {FLOOR:g}",
                 fontsize=10)
    save_figure(fig, "speed_vs_error_cavity.png")

    ue, ce = tight["global UMFPACK"], tight["global CHOLMOD"]
    out = [
        "## Cavity packing (hybrid, validation/cavity_packing)",
        "",
        f"Measured {datetime.date.today()}; the fastest of {CAVITY_REPEAT} runs of each setting, taken in turn (on this",
        f"shared machine the times still vary by some 20 % from one regeneration to the next; load average",
        f"{load[0]:.1f} before the runs, {os.getloadavg()[0]:.1f} after).",
        "",
        "The 27 grains in the cavity of the elastic square (validation/cavity_packing/README.md), relaxed",
        "by the global solver to the accuracy a (every grain's and boundary particle's fixing force",
        "below a). **Confined** (every radius x 1.15, the packing presses on the host; the main case):",
        f"the error is the distance from a tight run of the same scene with UMFPACK, a = {CAVITY_TIGHT:g} kgf",
        f"({ue[1]} iterations, {ue[0]:.3f} s; CHOLMOD: {ce[1]} iterations, {ce[0]:.3f} s): the largest",
        "distance of a grain's centre [cm], and the largest difference of the grains' force on a cavity",
        f"element over the largest such force ({top:.0f} kgf). The tight runs of CHOLMOD (which solves the",
        f"symmetric part of the host's K, unsymmetric by {100 * asym:.1f} %) and UMFPACK differ by {sym_pos:.1e} cm in",
        f"the grain positions and {sym_force:.1e} in the cavity forces: no CHOLMOD run can get closer.",
        f"The reference itself is {self_pos:.0e} cm from a run at a = {CAVITY_TIGHT / 100:g} kgf. The last column measures CHOLMOD",
        "against its own tight run (its convergence alone).",
        "",
        "**As placed** (the paper's scene): with no body force the grains separate until every overlap",
        "is gone, and a grain with no contact is in equilibrium wherever it stops, so its final place",
        f"depends on the path of the iteration (at a = {hi:g} UMFPACK and CHOLMOD end up to {apart:.1e} cm apart):",
        "no run is a reference for the positions. The well-defined measure is how far",
        "the result is from a state without overlaps: the largest overlap left (with the largest fixing",
        "force, below a by construction).",
        "",
        "The reference iteration does not run hybrid scenes, so only the global solver is measured:",
        f"`gembem` refuses them (\"{refusal.split(': ', 2)[-1]}\").",
        "",
        "![error against seconds](speed_vs_error_cavity.png)",
        "",
        "Confined:",
        "",
        "| solver | a [kgf] | iterations | seconds | largest fixing force [kgf] | grain position error [cm] | cavity force error | position error against its own tight run [cm] |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for r in rows["confined"]:
        out.append(f"| {r['solver']} | {r['a']:.0e} | {r['iters']} | {r['secs']:.4f} | {r['fixing']:.1e} | "
                   f"{r['pos']:.1e} | {r['force']:.1e} | {r['own']:.1e} |")
    out += ["", "As placed:", "",
            "| solver | a [kgf] | iterations | seconds | largest fixing force [kgf] | largest overlap left [cm] | contacts left |",
            "|---|---|---|---|---|---|---|"]
    for r in rows["placed"]:
        out.append(f"| {r['solver']} | {r['a']:.0e} | {r['iters']} | {r['secs']:.4f} | {r['fixing']:.1e} | "
                   f"{r['overlap']:.1e} | {r['contacts']} |")
    w = conf[hi]
    pl = [r for r in rows["placed"]]
    chol_open = all(r["contacts"] == 0 for r in pl if r["solver"] == "global CHOLMOD")
    gone = [r["a"] for r in pl if r["solver"] == "global UMFPACK" and r["overlap"] < FLOOR]
    worst_overlap = max(r["overlap"] for r in pl)
    out += [
        "",
        f"What to pick: CHOLMOD with a = 1e-3 kgf ({chol[1e-3]['secs']:.3f} s, {ratio:.0f} times faster than UMFPACK),",
        f"unless grain positions must be closer than about {sym_pos:.0e} cm or the cavity forces than",
        f"{sym_force:.0e} of the largest: both evaluate the forces with the exact host, but CHOLMOD's Newton steps,",
        "with the symmetrised host, take the frictional contacts along another path to a slightly different",
        "equilibrium, whatever a; then UMFPACK,",
        f"whose position error is about {slope:.1e} cm per kgf of a (a = 1e-4 kgf for {slope * 1e-4:.1e} cm), every",
        f"decade of a costing {per_decade:.0f} more iterations (about {100 * per_decade / conf[1e-3]['iters']:.0f} % more time).",
        "",
    ] + textwrap.wrap(
        f"The iterations grow by {per_decade:.0f} per decade of a: the convergence is linear (each iteration "
        f"divides the largest force by about {10 ** (1 / per_decade):.1f}), not Newton's quadratic one. At "
        f"a = {hi:g} the largest force left is on grain {w['worst']}, which has {w['worst_contacts']} "
        f"contact{'s' if w['worst_contacts'] != 1 else ''}"
        + ("; CHOLMOD and UMFPACK take the same iterations at every a" if same_iters else "") + ". "
        f"Frictionless, the same scene takes {nofric[0]} iterations at a = {lo:g} and {nofric[1]} at {hi:g} "
        f"({(nofric[1] - nofric[0]) / decades:.1f} per decade). With so few iterations per decade the time hardly "
        "depends on a: the linear solver, not a, sets the cost here.", 100) + [
        "",
    ] + textwrap.wrap(
        "As placed, " + ("CHOLMOD ends with every contact open (no overlap, no fixing force) whatever a; "
                         if chol_open else "") +
        "UMFPACK's path keeps a few contacts touching, with an overlap below a / kn"
        + (f" that vanishes from a = {max(gone):g} kgf" if gone else "") + "."
        + f" Both remove the 0.12 cm overlap of the placement; the largest overlap left at any a is {worst_overlap:.0e} cm.",
        100) + [""]
    return out


JAM_DIR = os.path.join(RUNS, "jammed1e4")
JAM_SOLVERS = {"reference": ("reference", "cholmod", (1e3, 1e2, 1e1, 1.0)),
               "global CHOLMOD": ("global", "cholmod", (1e3, 1e2, 1e1, 1.0, 1e-1)),
               "global UMFPACK": ("global", "umfpack", (1e3, 1e2, 1e1, 1.0, 1e-1))}
JAM_TIGHT = 1e-2  # a [dyn] of the tight runs
JAM_TIMEOUT = 200  # wall seconds: a reference run slower than this (about 3 minutes) is dropped


def jammed_packing():
    """The packing of tools/bench_gem.sh for 10 000 discs (tools/jammed_packing.sh), cached in
    runs/speed_vs_error/jammed1e4/. Returns (the box line, the mean of the packing's final wall stresses
    s_x, s_y [dyn/cm], the packing's log)."""
    d = JAM_DIR
    subprocess.run([os.path.join(ROOT, "tools", "jammed_packing.sh"), BUILD, d, "10000", "1", "10"], check=True,
                   env=dict(os.environ, KEEP="1"))
    box, log = (open(os.path.join(d, f)).read().strip() for f in ("jammed.box", "jammed.log"))
    m = re.search(r"wall stresses s_x ([-0-9.e+]+) s_y ([-0-9.e+]+)", log)
    return box, (float(m.group(1)) + float(m.group(2))) / 2, log


def jammed_scene(box, stress, method, linear, a):
    """The packing in its box (the line `box: {...}` of jammed.box), one isotropic stress step."""
    return gembem.Scene(
        units={"length": "cm", "force": "dyn"},
        materials={"grain_grain": {"kn": 1.0e8, "kt": 7.0e7, "friction_deg": 25},
                   "grain_wall": {"kn": 1.0e8, "kt": 7.0e7, "friction_deg": 0}},
        grains={"file": os.path.join(JAM_DIR, "jammed.csv")}, box=yaml.load(box, Loader=Loader)["box"],
        solver={"method": method, "linear": linear, "accuracy": a, "max_iterations": 2000000},
        loading=[{"isotropic": {"stress": float(f"{stress:.6e}"), "steps": 1}}])


def jammed_result(d):
    run = gembem.Run(d)
    g, s = run.state.grains, run.steps
    return {"grains": list(zip(g["x"].tolist(), g["y"].tolist())), "mean": float(s["s1"][-1] + s["s2"][-1]) / 2,
            "fixing": float(s["max_fixing_force"][-1])}


def jammed1e4_section():
    """10 000 jammed discs, one isotropic stress step: error against a tight run, over a and the solver."""
    os.environ["OPENBLAS_NUM_THREADS"] = "1"
    os.environ["OMP_NUM_THREADS"] = "1"
    box, s0, jamlog = jammed_packing()
    stress = 1.05 * s0
    load = os.getloadavg()
    tight = {}
    for solver in ("global UMFPACK", "global CHOLMOD"):
        method, lin, _ = JAM_SOLVERS[solver]
        d, secs, iters, _ = run_scene(f"jammed1e4_{lin}_tight", jammed_scene(box, stress, method, lin, JAM_TIGHT),
                                      repeat=1, fast=1.0, fast_repeat=3)
        tight[solver] = dict(jammed_result(d), secs=secs, iters=iters)
    exact = tight["global UMFPACK"]
    sym_pos = position_error(tight["global CHOLMOD"], exact)
    sym_mean = abs(tight["global CHOLMOD"]["mean"] - exact["mean"]) / exact["mean"]
    rows, dropped = [], []
    for solver, (method, lin, accs) in JAM_SOLVERS.items():
        for a in accs:
            name = f"jammed1e4_{method}_{lin}_a{a:g}"
            try:
                d, secs, iters, _ = run_scene(name, jammed_scene(box, stress, method, lin, a), repeat=1,
                                              fast=1.0, fast_repeat=3,
                                              timeout=JAM_TIMEOUT if method == "reference" else None)
            except subprocess.TimeoutExpired:
                dropped.append((solver, a))
                continue
            r = jammed_result(d)
            rows.append(dict(r, solver=solver, a=a, secs=secs, iters=iters, pos=position_error(r, exact),
                             serr=abs(r["mean"] - exact["mean"]) / exact["mean"]))
    load_after = os.getloadavg()

    fig, axes = plt.subplots(1, 2, figsize=(12, 4.8))
    for ax, (key, ylabel) in zip(axes, (("pos", "largest grain position error [cm]"),
                                        ("serr", "relative error of the mean stress (s1+s2)/2"))):
        for solver, mark in zip(JAM_SOLVERS, "osd"):
            pts = [(r["secs"], max(r[key], FLOOR), r["a"]) for r in rows if r["solver"] == solver]
            line, = ax.loglog([p[0] for p in pts], [p[1] for p in pts], mark + "-", label=solver)
            for x, y, a in pts:
                ax.annotate(f"{a:g}", (x, y), fontsize=7, color=line.get_color(), xytext=(3, 3),
                            textcoords="offset points")
        ax.axhline(max(sym_pos if key == "pos" else sym_mean, FLOOR), color="grey", ls=":",
                   label=f"CHOLMOD's tight run (a = {JAM_TIGHT:g})")
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_xlabel("seconds (solver only, 1 OpenBLAS thread)")
        ax.set_ylabel(ylabel)
        ax.legend(fontsize=8)
    fig.suptitle(f"10 000 jammed discs, one isotropic stress step to {stress:.4g} dyn/cm: error against cost, "
                 f"a [dyn] on the labels; against UMFPACK at a = {JAM_TIGHT:g}", fontsize=10)
    save_figure(fig, "speed_vs_error_jammed1e4.png")

    out = [
        "## 10 000 jammed discs, isotropic compression",
        "",
        f"Measured {datetime.date.today()}; each setting run once (runs under a second: the fastest of 3);",
        f"OPENBLAS_NUM_THREADS=1, OMP_NUM_THREADS=1; load average {load[0]:.1f} before the runs,",
        f"{load_after[0]:.1f} after (shared machine: two regenerations on 2026-11-22 gave the same settings times up to 1.6 times apart).",
        "",
    ] + textwrap.wrap(
        "The packing of tools/bench_gem.sh: `tools/jammed_packing.sh BUILD DIR 10000 1 10`, gembem pack's growth "
        "of the paper's three sizes to porosity 0.15 in a fixed box, FIRE to |F| <= 10 dyn, then gembem's solver "
        f"(\"{jamlog.split(': ', 1)[-1]}\"). "
        "The scene: kn, kt = 1e8, 7e7 dyn/cm, friction 25 deg between grains and 0 against the walls; one "
        f"load step of isotropic stress control from the walls' stresses to 1.05 x their mean, {stress:.5g} dyn/cm. "
        "The error is the distance from a tight run of the same scene with global UMFPACK at "
        f"a = {JAM_TIGHT:g} dyn ({exact['iters']} iterations, {exact['secs']:.2f} s; CHOLMOD at the same a: "
        f"{tight['global CHOLMOD']['iters']} iterations, {tight['global CHOLMOD']['secs']:.2f} s, its grains up to "
        f"{sym_pos:.1e} cm and its mean stress {sym_mean:.1e} (relative) from UMFPACK's): "
        "the largest distance of a grain's centre [cm], and the relative difference of the mean stress "
        "(s1 + s2) / 2 of the last row of steps.csv.", 100) + [
        "",
        "![error against seconds](speed_vs_error_jammed1e4.png)",
        "",
        "| solver | a [dyn] | iterations | seconds | largest fixing force [dyn] | grain position error [cm] | mean stress error |",
        "|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        out.append(f"| {r['solver']} | {r['a']:g} | {r['iters']} | {r['secs']:.2f} | {r['fixing']:.1e} | "
                   f"{r['pos']:.1e} | {r['serr']:.1e} |")
    if dropped:
        out += ["", "Dropped (more than %d s of wall time, stopped): %s." % (
            JAM_TIMEOUT, ", ".join(f"{s} at a = {a:g}" for s, a in dropped))]
    pos_tol = 1e-3  # cm, 1/600 of the smallest diameter
    good = [r for r in rows if r["pos"] <= pos_tol]
    pick = min(good, key=lambda r: r["secs"]) if good else min(rows, key=lambda r: r["pos"])
    ref = {r["a"]: r for r in rows if r["solver"] == "reference"}
    fastest_ref = min(ref.values(), key=lambda r: r["secs"]) if ref else None
    text = (f"What to pick: {pick['solver']} with a = {pick['a']:g} dyn ({pick['secs']:.1f} s, {pick['iters']} "
            f"iterations, grain positions {pick['pos']:.0e} cm and the mean stress {pick['serr']:.0e} from the tight run)"
            + (f", the cheapest setting whose grains are within {pos_tol:g} cm of the tight run" if good else
               f"; no setting got the grains within {pos_tol:g} cm of the tight run") + ".")
    if fastest_ref is not None and pick["solver"] != "reference":
        text += (f" The reference iteration's cheapest run (a = {fastest_ref['a']:g}: {fastest_ref['secs']:.1f} s, "
                 f"{fastest_ref['iters']} iterations) leaves the grains {fastest_ref['pos']:.0e} cm off.")
    out += [""] + textwrap.wrap(text, 100) + [""]
    refs = sorted((r for r in rows if r["solver"] == "reference"), key=lambda r: r["a"])
    if len(refs) >= 2:
        lo, nxt = refs[0], refs[1]
        far = sum(math.hypot(p[0] - q[0], p[1] - q[1]) > 1e-4 for p, q in zip(lo["grains"], exact["grains"]))
        out += textwrap.wrap(
            f"The reference iteration's position error does not fall with a: its runs at a = {lo['a']:g} and "
            f"{nxt['a']:g} are {position_error(lo, nxt):.1e} cm apart (it converges), yet at a = {lo['a']:g} {far} of "
            f"the 10 000 grains end more than 1e-4 cm (at most {lo['pos']:.1e} cm) from where the global solver "
            "puts them, while the mean stress agrees to its a: with friction the equilibrium reached depends on "
            "the path of the iteration, and the two solvers take different paths. The global runs converge "
            f"to one another down to {sym_pos:.1e} cm, the distance between CHOLMOD's and UMFPACK's tight "
            "runs, below which CHOLMOD does not go.", 100) + [""]
    return out


# part: (the start of its section's heading, the function that measures it and returns the section)
PARTS = {"three_discs": ("## Three discs", three_discs_section),
         "bem": ("## Boundary elements", bem_section),
         "cavity": ("## Cavity packing", cavity_section),
         "jammed1e4": ("## 10 000 jammed discs", jammed1e4_section)}


def sections(lines):
    """The sections of a markdown text as {heading line: lines}, and the header before them."""
    head, out, cur = [], {}, None
    for line in lines:
        if line.startswith("## "):
            cur = line
            out[cur] = []
        (head if cur is None else out[cur]).append(line)
    return head, out


def main():
    global BUILD
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("build", nargs="?", default="build", help="build directory (default build)")
    ap.add_argument("--only", help="comma-separated parts to rerun: " + ", ".join(PARTS))
    args = ap.parse_args()
    BUILD = os.path.join(ROOT, args.build)
    only = args.only.split(",") if args.only else list(PARTS)
    for p in only:
        if p not in PARTS:
            sys.exit(f"unknown part {p!r}: one of {', '.join(PARTS)}")
    old = sections(open(MD).read().splitlines())[1] if os.path.exists(MD) else {}
    cpu = "unknown"
    for line in open("/proc/cpuinfo"):
        if line.startswith("model name"):
            cpu = line.split(":", 1)[1].strip()
            break
    out = [
        "# Speed against error",
        "",
        "Regenerate with `tools/speed_vs_error.py [BUILD_DIR]`, or one part with `--only " + "|".join(PARTS) + "`",
        f"(the other sections stay). {os.cpu_count()} cores, {cpu}, {platform.system()}; seconds of the",
        "solver alone as summed in steps.csv, the fastest of several runs.",
        "",
    ]
    for p, (heading, fn) in PARTS.items():
        if p in only:
            new = fn()
            print("\n".join(new))
            out += new
        else:  # keep the section from the last run, matched by the heading the part writes
            kept = [v for k, v in old.items() if k.startswith(heading)]
            if kept:
                out += kept[0]
    with open(MD, "w") as f:
        f.write("\n".join(out).rstrip("\n") + "\n")


if __name__ == "__main__":
    main()
