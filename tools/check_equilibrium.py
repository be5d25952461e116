#!/usr/bin/python3
"""Checks that a run's final state is a frictional equilibrium, independently of gembem's code.

    tools/check_equilibrium.py RUN_DIR [--accuracy A] [--slack S]

Reads RUN_DIR/scene.yaml (materials, body force), RUN_DIR/state.yaml (the box) and the
state's grains and contacts CSV files, and recomputes from the positions alone, with its own
contact detection (a k-d tree, scipy): every overlap d = r_i + r_j - |x_j - x_i| (or the distance
into a wall), the normal force pn = kn d of docs/method.md section 3 (K 3), and from the stored
tangential forces pt (one per contact: K 6 is path-dependent, so pt cannot be recomputed from
the positions) each grain's fixing force (K 5): sum over its contacts of pn n + pt t (n from the
grain to the other side, t = (-ny, nx)) minus its body force, and its moment over its radius,
sum of pt, minus the rolling moment mr / r_i on grain i and plus mr / r_j on grain j when the
contacts file has the column mr (rolling resistance, docs/method.md section 3.1: stored like pt,
path-dependent). It checks:
  - every grain's |(Fx, Fy, M/r)| <= A (K 14), A the last step's accuracy (steps.csv) unless given;
  - Coulomb without dilation (K 13): |pt| <= pn tan(phi) + c, to S (relative, 1e-9) of the cap;
  - with rolling resistance, the rolling limit |mr| <= eta R* pn, R* = r_i r_j / (r_i + r_j)
    (r_i against a wall), to S of the limit;
  - every stored contact is an overlap at the stored positions, with its stored pn = kn d to S
    (both beyond the rounding of an overlap computed from the coordinates, kn 1e3 eps |x|max),
    and every overlap found is a stored contact (an overlap with no stored contact carries pt = 0).
Prints the largest values, then a second line describing the state (grain-grain and grain-wall
contacts found, and in a box the walls' stresses s1 = vertical, s2 = horizontal: the walls'
normal forces over twice the side, compression positive, dyn/cm for cgs scenes, K section 4.1),
and exits 0 when all hold, 1 when one fails, 2 on unusable input.
Host scenes (boundary particles) are refused: their forces need the host's stiffness.
"""
import argparse
import math
import os
import sys

import numpy as np
import yaml
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from gembem import read_csv  # noqa: E402  (the package's one CSV reader, not gembem's C code)

WALLS = ("left", "right", "bottom", "top")


def fail_input(msg):
    print(f"check_equilibrium: {msg}", file=sys.stderr)
    sys.exit(2)


def load_yaml(path):
    try:
        with open(path) as f:
            return yaml.safe_load(f)
    except (OSError, yaml.YAMLError) as e:
        fail_input(f"{path}: {e}")


def material(scene, key):
    m = (scene.get("materials") or {}).get(key)
    if m is None:
        return None
    rolling = m.get("rolling") or {}
    return {"kn": float(m["kn"]), "kt": float(m.get("kt", 0)),
            "tan_phi": math.tan(math.radians(float(m.get("friction_deg", 0)))),
            "cohesion": float(m.get("cohesion", 0)), "eta": float(rolling.get("eta", 0))}


def body_force_per_area(scene):
    b = scene.get("body_force")
    if not b:
        return np.zeros(2)
    if "weight_per_area" in b:
        return np.array([0.0, -float(b["weight_per_area"])])
    return float(b["density"]) * np.array([float(v) for v in b["gravity"]])


def read_table(path):
    try:
        return read_csv(path)
    except (OSError, ValueError) as e:
        fail_input(str(e))


def last_accuracy(run_dir):
    """The accuracy a that the last step was solved to: steps.csv's `accuracy` (a relative
    accuracy resolves to a force per step)."""
    try:
        return float(read_csv(os.path.join(run_dir, "steps.csv"))["accuracy"][-1])
    except (OSError, KeyError, IndexError, ValueError) as e:
        fail_input(f"{run_dir}/steps.csv: no accuracy of the last step ({e})")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run_dir")
    ap.add_argument("--accuracy", type=float, help="largest fixing force allowed (default: the scene's)")
    ap.add_argument("--slack", type=float, default=1e-9, help="relative slack on Coulomb and pn = kn d")
    a = ap.parse_args()

    scene = load_yaml(os.path.join(a.run_dir, "scene.yaml"))
    state_path = os.path.join(a.run_dir, "state.yaml")
    state = load_yaml(state_path)
    if scene.get("host"):
        fail_input("host scenes are not checked (the particles' forces need the host's stiffness)")
    gg, gw = material(scene, "grain_grain"), material(scene, "grain_wall")
    if gg is None:
        fail_input("scene.yaml: no materials.grain_grain")
    accuracy = a.accuracy if a.accuracy is not None else last_accuracy(a.run_dir)
    box = state.get("box")
    files = state["grains"]
    base = os.path.dirname(state_path)
    g = read_table(os.path.join(base, files["file"]))
    grains = np.column_stack([g["x"], g["y"], g["r"]]).astype(float).reshape(-1, 3)
    stored = read_table(os.path.join(base, files["contacts"]))
    rolling = "mr" in stored
    n = len(grains)
    x, r = grains[:, :2], grains[:, 2]

    # The overlaps, found from the positions alone.
    tree = cKDTree(x)
    found = {}
    for i, j in tree.query_pairs(2 * r.max()):
        i, j = min(i, j), max(i, j)
        bv = x[j] - x[i]
        dist = math.hypot(*bv)
        d = r[i] + r[j] - dist
        if d > 0:
            found[(i, j)] = (d, bv / dist)
    if box:
        if gw is None:
            fail_input("scene.yaml: a box but no materials.grain_wall")
        gaps = {"left": (x[:, 0] - box["left"], (-1.0, 0.0)), "right": (box["right"] - x[:, 0], (1.0, 0.0)),
                "bottom": (x[:, 1] - box["bottom"], (0.0, -1.0)), "top": (box["top"] - x[:, 1], (0.0, 1.0))}
        for w, (gap, nrm) in gaps.items():
            for i in np.nonzero(r - gap > 0)[0]:
                found[(int(i), w)] = (r[i] - gap[i], np.array(nrm))

    # An overlap is a difference of nearly equal lengths (r_i + r_j - |x_j - x_i|): computed twice
    # (here and in gembem) it agrees to a few units of rounding of the coordinates, not of d.
    d_round = 1e3 * np.finfo(float).eps * max(float(np.abs(x).max()) if n else 1.0, float(r.max()) if n else 1.0)
    F = np.zeros((n, 3))
    F[:, :2] -= body_force_per_area(scene)[None, :] * (math.pi * r * r)[:, None]
    worst_coulomb = worst_pn = worst_rolling = 0.0
    problems = []
    seen = set()
    for i, side, pn_stored, pt, mr in zip(stored["i"].tolist(), stored["j"].astype(str).tolist(), stored["pn"].tolist(),
                                          stored["pt"].tolist(), stored["mr"].tolist() if rolling else [0.0] * stored.nrows):
        key = (i, side) if side in WALLS else (i, int(side))
        if key in seen:
            problems.append(f"contact {key} stored twice")
        seen.add(key)
        if key not in found:
            problems.append(f"stored contact {key} is not an overlap at the stored positions")
            continue
        d, nrm = found[key]
        mat = gw if side in WALLS else gg
        pn = mat["kn"] * d
        worst_pn = max(worst_pn, (abs(pn - pn_stored) - mat["kn"] * d_round) / pn)
        cap = pn * mat["tan_phi"] + mat["cohesion"]
        worst_coulomb = max(worst_coulomb, (abs(pt) - cap - mat["kn"] * d_round * mat["tan_phi"]) / max(cap, 1e-300))
        t = np.array([-nrm[1], nrm[0]])
        f = pn * nrm + pt * t
        rstar = r[i] if side in WALLS else r[i] * r[int(side)] / (r[i] + r[int(side)])
        mcap = mat["eta"] * rstar * pn
        worst_rolling = max(worst_rolling, (abs(mr) - mcap - mat["eta"] * rstar * mat["kn"] * d_round) / max(mcap, 1e-300))
        F[i, :2] += f
        F[i, 2] += pt - mr / r[i]
        if side not in WALLS:
            j = int(side)
            F[j, :2] -= f
            F[j, 2] += pt + mr / r[j]
    for key, (d, nrm) in found.items():
        if key not in seen:  # an overlap without a stored contact: pt = 0 (a contact that just touched)
            mat = gw if isinstance(key[1], str) else gg
            F[key[0], :2] += mat["kn"] * d * nrm
            if not isinstance(key[1], str):
                F[key[1], :2] -= mat["kn"] * d * nrm
    norms = np.sqrt((F * F).sum(axis=1))
    k = int(np.argmax(norms)) if n else 0
    print(f"{a.run_dir}: {n} grains, {stored.nrows} stored contacts, {len(found)} overlaps found; "
          f"largest fixing force {norms[k]:.6g} dyn (grain {k}, accuracy {accuracy:g}); "
          f"Coulomb excess {max(worst_coulomb, 0):.3g} of the cap; pn against kn d {max(worst_pn, 0):.3g} (relative)"
          + (f"; rolling excess {max(worst_rolling, 0):.3g} of the limit" if stored.nrows and rolling else ""))
    if norms[k] > accuracy:
        problems.append(f"grain {k}: fixing force {norms[k]:.6g} > accuracy {accuracy:g}")
    if worst_coulomb > a.slack:
        problems.append(f"a tangential force exceeds its Coulomb cap by {worst_coulomb:.3g} of the cap")
    if worst_rolling > a.slack:
        problems.append(f"a rolling moment exceeds its limit eta R* pn by {worst_rolling:.3g} of the limit")
    if worst_pn > a.slack:
        problems.append(f"a stored normal force differs from kn d by {worst_pn:.3g} (relative)")
    gg_found = sum(1 for key in found if not isinstance(key[1], str))
    line = f"  state: {gg_found} grain-grain contacts, {len(found) - gg_found} grain-wall contacts"
    if box:
        wall = {w: 0.0 for w in WALLS}
        for key, (d, _) in found.items():
            if isinstance(key[1], str):
                wall[key[1]] += gw["kn"] * d
        width, height = box["right"] - box["left"], box["top"] - box["bottom"]
        line += (f"; wall stresses s1 {(wall['bottom'] + wall['top']) / (2 * width):.6g}, "
                 f"s2 {(wall['left'] + wall['right']) / (2 * height):.6g}")
    print(line)
    for p in problems[:10]:
        print(f"  FAIL {p}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
