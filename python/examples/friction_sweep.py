#!/usr/bin/python3
"""A parameter sweep from Python: the three discs with 0-15 deg of friction against the walls.

    PYTHONPATH=python python/examples/friction_sweep.py OUT_DIR [--angles 0 5 10 15] [--jobs 2]

Kishino (1989) Fig. 7: case 1's three discs, 25 deg of friction between the discs and phi'
against the walls. Instead of one hand-made YAML file per angle (validation/three_discs/
friction_wall*.yaml), the validated scene is loaded once, one value changed per case, and each
case run in this process by gembem's library (gembem.Simulation, docs/python.md), its steps'
reports kept: no run directories (a Snakemake study runs the command instead:
studies/examples/three_discs). Writes OUT_DIR/friction_sweep.png (stress ratio against shear
strain, the rigid frictionless solution dashed) and prints the stress ratio at e1 - e2 =
1..5 %. With --jobs N, N cases run at once (threads: the library runs outside Python's lock).
"""
import argparse
import os
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np

import gembem
import gembem.figures as figures

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(ROOT, "validation", "three_discs"))
from table2 import exact_ratio  # noqa: E402  (the rigid solution, (K 19)-(K 21))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("--angles", type=float, nargs="+", default=[0, 5, 10, 15])
    ap.add_argument("--jobs", type=int, default=1, help="cases run at once")
    a = ap.parse_args()

    base = gembem.Scene.load(os.path.join(ROOT, "validation", "three_discs", "case1.yaml"))
    base = base.with_value("materials.grain_grain.friction_deg", 25)
    os.makedirs(a.out, exist_ok=True)

    def case(phi):
        scene = base.with_value("materials.grain_wall.friction_deg", phi)
        with gembem.Simulation(scene, name=os.path.join(a.out, f"{phi:g}.yaml")) as sim:
            sim.run()                            # every step, in this process
        return sim                               # its steps (a Table, as steps.csv's) stay

    with ThreadPoolExecutor(max_workers=a.jobs) as pool:
        runs = list(pool.map(case, a.angles))

    labels = [f"phi' = {phi:g} deg" for phi in a.angles]
    fig = figures.stress_strain(runs, labels=labels, stages=[2])
    ax = fig.axes[0]
    g = np.linspace(1e-6, 0.05, 200)
    ax.plot(100 * g, [exact_ratio(v) for v in g], "k--", lw=1, label="exact (rigid, frictionless)")
    ax.set_xlim(0, 5)
    ax.set_ylim(0, 1.1)
    ax.set_ylabel("(s1 - s2) / (s1 + s2)")
    ax.set_title("three discs, phi = 25 deg between discs (cf. Kishino 1989, Fig. 7)", fontsize=10)
    ax.legend(fontsize=8, loc="lower right")
    fig.savefig(os.path.join(a.out, "friction_sweep.png"), dpi=120)

    print("| phi' | " + " | ".join(f"{k} %" for k in range(1, 6)) + " |")
    print("|---|" + "---|" * 5)
    for phi, run in zip(a.angles, runs):
        s = run.steps.select(run.steps["stage"] == 2)
        at = [s["stress_ratio"][np.argmin(np.abs(s["e1_minus_e2"] - 0.01 * k))] for k in range(1, 6)]
        print(f"| {phi:g} deg | " + " | ".join(f"{v:.4f}" for v in at) + " |")
    print(f"figure: {os.path.join(a.out, 'friction_sweep.png')}", file=sys.stderr)


if __name__ == "__main__":
    main()
