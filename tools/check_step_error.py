#!/usr/bin/python3
"""Recomputes the last step's error columns of a run's steps.csv from its saved state.

    tools/check_step_error.py RUN_DIR [--tolerance T]

Reads the run with the gembem package (python/): scene.yaml (materials, body force, loading),
state.yaml with its grains and contacts (the final state, the last step's end), steps.csv's last
row, and when present contacts/contacts_NNNNNN.csv of the step before (the last step's start) and
host_particles.csv (the host's K u + f0 at the end). From the stored contact forces alone (pn, pt
and the normal of every contact: tools/check_equilibrium.py checks those against the positions),
by its own sums, it recomputes (docs/run-directory.md, steps.csv):
  - force_scale: the larger of the mean pn of the step's start contacts (overlap above 1e3 eps of
    the coordinates) and the stage's load force (target stress x mean diameter, mean weight);
  - relative_residual: the largest grain fixing force (K 5: contacts minus body force, moment / r,
    with the rolling moments mr of the contacts file when it has them, docs/method.md section 3.1)
    over the scale;
  - relative_wall_residual (stress-controlled stages): the walls' force error against the stage's
    final target over the scale;
  - host_balance (hosts): the largest |K u + f0 - grains' force| over the boundary particles;
  - coulomb_excess: max |pt| - (pn tan phi + c) over the contacts, over the scale;
  - mean_normal_force, coordination (contacts per grain with two or more) and rattlers.
Each must agree with steps.csv to T (relative to the scale, default 1e-9; the forces are sums of
contact forces that cancel, their rounding is of that order). Exits 0 when all agree, 1 if not.
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
import gembem  # noqa: E402

WALLS = ("left", "right", "bottom", "top")


def material(scene, kind):
    m = scene["materials"].get(kind)
    if m is None:  # grain_boundary's default: the grain_grain kn, normal springs only
        m = {"kn": scene["materials"]["grain_grain"]["kn"], "kt": 0, "friction_deg": 0}
    return math.tan(math.radians(float(m.get("friction_deg", 0)))), float(m.get("cohesion", 0))


def body_per_area(scene):
    b = scene.get("body_force") or {}
    if "weight_per_area" in b:
        return np.array([0.0, -float(b["weight_per_area"])])
    if "gravity" in b:
        return float(b["density"]) * np.array([float(v) for v in b["gravity"]])
    return np.zeros(2)


def stage_of(scene, stage):
    kind, values = next(iter(scene["loading"][stage - 1].items()))
    return kind, values or {}


def load_force(scene, r, stage):
    weight = float(np.hypot(*body_per_area(scene))) * float(np.mean(math.pi * r * r))
    kind, v = stage_of(scene, stage)
    stress = {"isotropic": lambda: v["stress"], "biaxial_stress": lambda: max(v["s1"], v["s2"]),
              "shear_mean_stress": lambda: v["mean_stress"]}.get(kind, lambda: 0.0)()
    return max(weight, float(stress) * 2 * float(np.mean(r)))


def mean_pn(contacts, extent):
    d = np.asarray(contacts["overlap"], dtype=float)
    pn = np.asarray(contacts["pn"], dtype=float)[d > 1e3 * np.finfo(float).eps * extent]
    return float(pn.mean()) if len(pn) else 0.0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run_dir")
    ap.add_argument("--tolerance", type=float, default=1e-9)
    a = ap.parse_args()
    run = gembem.Run(a.run_dir)
    scene, state, steps = run.scene, run.state, run.steps
    last = {k: v[-1] for k, v in steps.items()}
    step, stage = int(last["step"]), int(last["stage"])
    g, c = state.grains, state.contacts
    n = g.nrows
    x, y, r = (np.asarray(g[k], dtype=float) for k in ("x", "y", "r"))
    box = state.box
    extent = max(abs(float(box[k])) for k in WALLS)
    got = {}

    # the scale, from the step's start when its contacts were kept
    start = os.path.join(a.run_dir, "contacts", f"contacts_{step - 1:06d}.csv")
    if os.path.exists(start):
        got["force_scale"] = max(mean_pn(gembem.read_csv(start), extent), load_force(scene, r, stage))
    scale = got.get("force_scale", float(last["force_scale"]))

    F = np.zeros((n, 3))
    F[:, :2] -= body_per_area(scene)[None, :] * (math.pi * r * r)[:, None]
    count = np.zeros(n, dtype=int)
    wall = {w: 0.0 for w in WALLS}
    particle = {}
    excess = -math.inf
    # the rolling moment on grain i (docs/method.md section 3.1), a column only with rolling resistance
    mrs = c["mr"] if "mr" in c else np.zeros(c.nrows)
    for i, j, pn, pt, nx, ny, mr in zip(c["i"], c["j"], c["pn"], c["pt"], c["nx"], c["ny"], mrs):
        i, j, pn, pt, mr = int(i), str(j), float(pn), float(pt), float(mr)
        f = pn * np.array([nx, ny]) + pt * np.array([-ny, nx])
        F[i, :2] += f
        F[i, 2] += pt - mr / r[i]
        count[i] += 1
        kind = "grain_wall" if j in WALLS else "grain_boundary" if j.startswith("p") else "grain_grain"
        tan_phi, coh = material(scene, kind)
        excess = max(excess, abs(pt) - (pn * tan_phi + coh))
        if j in WALLS:
            wall[j] += pn
        elif j.startswith("p"):
            particle[int(j[1:])] = particle.get(int(j[1:]), 0) + f
        else:
            F[int(j), :2] -= f
            F[int(j), 2] += pt + mr / r[int(j)]
            count[int(j)] += 1
    got["relative_residual"] = float(np.sqrt((F * F).sum(axis=1)).max()) / scale
    got["coulomb_excess"] = excess / scale
    got["mean_normal_force"] = mean_pn(c, extent)
    carrying = count >= 2
    got["coordination"] = float(count[carrying].sum() / carrying.sum()) if carrying.any() else 0.0
    got["rattlers"] = int(n - carrying.sum())
    kind, v = stage_of(scene, stage)
    W, H = float(box["right"]) - float(box["left"]), float(box["top"]) - float(box["bottom"])
    if kind in ("isotropic", "biaxial_stress") and not scene.get("host"):
        s1, s2 = (v["stress"], v["stress"]) if kind == "isotropic" else (v["s1"], v["s2"])
        err = max(abs(s1 * W - 0.5 * (wall["bottom"] + wall["top"])), abs(s2 * H - 0.5 * (wall["left"] + wall["right"])))
        got["relative_wall_residual"] = err / scale
    elif kind == "shear_mean_stress":
        mean = 0.5 * ((wall["bottom"] + wall["top"]) / (2 * W) + (wall["left"] + wall["right"]) / (2 * H))
        got["relative_wall_residual"] = abs(v["mean_stress"] - mean) * 0.5 * (W + H) / scale
    if scene.get("host") and not scene["host"].get("rigid"):
        p = run.host_particles
        worst = 0.0
        for k, (hx, hy) in enumerate(zip(p["host_fx"], p["host_fy"])):
            fk = particle.get(k, np.zeros(2))
            worst = max(worst, math.hypot(hx - fk[0], hy - fk[1]))
        got["host_balance"] = worst / scale

    bad = 0
    for k, value in got.items():
        want = float(last[k])
        # the counts exactly; the forces over the scale to T; mean_normal_force relative to itself
        tol = 0 if k == "rattlers" else a.tolerance * (abs(value) if k == "mean_normal_force" else 1) + \
            (1e-6 * abs(value) if k != "force_scale" else 1e-12 * value)
        ok = abs(value - want) <= tol
        bad += not ok
        print(f"{'ok  ' if ok else 'FAIL'} step {step} {k}: recomputed {value:.10g}, steps.csv {want:.10g}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
