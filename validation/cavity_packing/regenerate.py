#!/usr/bin/python3
"""Validation C: runs the cavity packing as placed (scene.yaml) and confined (every radius x 1.15,
cavity.py) with UMFPACK and with CHOLMOD, draws the figures and prints the table of README.md.

usage: validation/cavity_packing/regenerate.py [BUILD_DIR]     (default: build)
Runs in runs/cavity_packing/CASE-SOLVER (each beside its scene, CASE-SOLVER.yaml).
"""
import os
import subprocess
import sys

import numpy as np

from cavity import CASES, HERE, gembem, cavity_scene

ROOT = os.path.dirname(os.path.dirname(HERE))
SOLVERS = ("umfpack", "cholmod")


def main():
    build = os.path.join(ROOT, sys.argv[1] if len(sys.argv) > 1 else "build")
    runs = os.path.join(ROOT, "runs", "cavity_packing")
    done = {}
    for case in CASES:
        for lin in SOLVERS:
            done[case, lin] = gembem.run(cavity_scene(case, linear=lin), os.path.join(runs, f"{case}-{lin}"),
                                         overwrite=True, quiet=True, gembem=os.path.join(build, "gembem"))
    for case in CASES:
        subprocess.run([sys.executable, os.path.join(HERE, "figures.py"), done[case, "umfpack"].path,
                        os.path.join(HERE, case), f"Cavity packing, {case} (UMFPACK)"], check=True)
    print("| case | solver | iterations | seconds | largest fixing force [kgf] | largest overlap [cm] | "
          "contacts with the cavity | ||K-K^t||/||K|| |")
    print("|---|---|---|---|---|---|---|---|")
    for (case, lin), run in done.items():
        s, c = run.steps, run.state.contacts
        overlap = max(float(np.max(c["overlap"], initial=0.0)), 0.0)
        cavity = int(np.sum(np.char.startswith(c["j"].astype(str), "p")))
        print(f"| {case} | {lin.upper()} | {s['iterations'][-1]} | {s['seconds'][-1]:.3f} | "
              f"{s['max_fixing_force'][-1]:.2e} | {overlap:.2e} | {cavity} | {float(run.host_info['asymmetry']):.2e} |")
    for case in CASES:
        a, b = (done[case, lin].state.grains for lin in SOLVERS)
        d = np.max(np.hypot(a["x"] - b["x"], a["y"] - b["y"]))
        print(f"\n{case}: final grain positions of UMFPACK and CHOLMOD differ by {d:.2e} cm at most.")


if __name__ == "__main__":
    main()
