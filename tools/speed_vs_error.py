#!/usr/bin/python3
"""Speed against error (a benchmark, not a test): the three-disc shear test of Kishino (1989)
run over kn, the accuracy a, alpha and the solver; the error is the largest distance of the stress
ratio from the rigid exact solution (METHOD.md section 7) at e1 - e2 = 1..5 %, the cost the
solver's seconds (steps.csv, the sum over all steps, without start-up and output).

usage: tools/speed_vs_error.py [BUILD_DIR]
Then the boundary element module: Lame's annulus and Kirsch's hole refined (build/speed_error_bem).
writes validation/SPEED_VS_ERROR.md, validation/speed_vs_error_three_discs.png and
validation/speed_vs_error_bem.png
"""
import csv
import datetime
import os
import platform
import re
import subprocess
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "validation", "three_discs"))
from table2 import exact_ratio  # noqa: E402

BUILD = os.path.join(ROOT, sys.argv[1] if len(sys.argv) > 1 else "build")
RUNS = os.path.join(ROOT, "runs", "speed_vs_error")
BASE = open(os.path.join(ROOT, "validation", "three_discs", "case1.yaml")).read()
SOLVERS = {"reference": "method: reference", "global CHOLMOD": "method: global\n  linear: cholmod",
           "global UMFPACK": "method: global\n  linear: umfpack"}


def run(kn, a, alpha, solver, repeat=3):
    text = BASE.replace("kn: 1.0e8, kt: 7.0e7", f"kn: {kn:.1e}, kt: {0.7 * kn:.1e}")
    text = text.replace("accuracy: 100 ", f"accuracy: {a} ").replace("alpha: 0.75", f"alpha: {alpha}")
    text = text.replace("solver:\n", "solver:\n  " + SOLVERS[solver] + "\n")
    name = f"kn{kn:.0e}_a{a}_alpha{alpha}_{solver.replace(' ', '_')}"
    d = os.path.join(RUNS, name)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "scene.yaml"), "w") as f:
        f.write(text)
    best = None
    for _ in range(repeat):  # the fastest of a few runs: the machine is shared
        subprocess.run([os.path.join(BUILD, "gembem"), "run", os.path.join(d, "scene.yaml"), "-o",
                        os.path.join(d, "run"), "--overwrite", "--quiet"], check=True)
        rows = list(csv.DictReader(open(os.path.join(d, "run", "steps.csv"))))
        secs = sum(float(r["seconds"]) for r in rows)
        best = secs if best is None else min(best, secs)
    err = 0.0
    iters = sum(int(r["iterations"]) for r in rows)
    for r in rows:
        if r["stage"] == "2":
            g = float(r["e1_minus_e2"])
            for k in range(1, 6):
                if abs(g - 0.01 * k) < 1e-9:
                    err = max(err, abs(float(r["stress_ratio"]) - exact_ratio(0.01 * k)))
    return err, best, iters


def bem_section():
    """Lame and Kirsch: error against seconds as the elements are refined (one dense LU each)."""
    env = dict(os.environ, OPENBLAS_NUM_THREADS="2")
    text = subprocess.run([os.path.join(BUILD, "speed_error_bem")], cwd=ROOT, env=env, check=True,
                          capture_output=True, text=True).stdout
    rows = list(csv.DictReader(text.splitlines()))
    fig, ax = plt.subplots(figsize=(7, 5))
    for case, mark, label in (("lame", "o-", "Lame annulus, u_r on the cavity"),
                              ("kirsch", "s-", "Kirsch, hoop stress at r = 1.5 a")):
        pts = [(float(r["seconds"]), float(r["error"])) for r in rows if r["case"] == case]
        ax.loglog([p[0] for p in pts], [p[1] for p in pts], mark, label=label)
    ax.set_xlabel("seconds (mesh, assembly, dense LU solve; 2 OpenBLAS threads)")
    ax.set_ylabel("relative error")
    ax.set_title("Boundary elements: error against cost, 16 to 1024 elements per circle")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "validation", "speed_vs_error_bem.png"), dpi=110)
    out = ["## Boundary elements: Lame and Kirsch", "",
           "Lame's annulus 1 < r < 2 (inner pressure, outer fixed, plane strain, nu = 0.3): the largest",
           "relative error of u_r on the cavity; Kirsch (a hole of radius 1 in an infinite plane under",
           "s_xx = 1): the hoop stress at r = 1.5 on the vertical axis from an interior point. N elements per",
           "circle; seconds for meshing (gmsh), assembly and the dense solve, the fastest of 3 runs.", "",
           "![error against seconds](speed_vs_error_bem.png)", "",
           "| case | N | seconds | error |", "|---|---|---|---|"]
    for r in rows:
        out.append(f"| {r['case']} | {r['N']} | {float(r['seconds']):.4f} | {float(r['error']):.2e} |")
    out += ["", "What to pick: constant elements converge at first order on the boundary (the error halves",
            "when N doubles, while the cost grows like N^2 to N^3): for 1e-3 on boundary displacements",
            "take about 400 elements per circle (0.1 s). Interior stresses half a radius away from the",
            "hole converge much faster (Kirsch: 3e-5 at 128 elements) until the interior",
            "quadrature's own tolerance, about 2e-6, takes over.", ""]
    return out


def main():
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
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "validation", "speed_vs_error_three_discs.png"), dpi=110)

    cpu = "unknown"
    for line in open("/proc/cpuinfo"):
        if line.startswith("model name"):
            cpu = line.split(":", 1)[1].strip()
            break
    out = [
        "# Speed against error",
        "",
        f"Regenerate with `tools/speed_vs_error.py` (measured {datetime.date.today()}, {os.cpu_count()} cores, {cpu},",
        f"{platform.system()}; the fastest of 3 runs, seconds of the solver alone as summed in steps.csv).",
        "",
        "## Three discs (Kishino 1989, section 3)",
        "",
        "Error: the largest distance of the stress ratio from the rigid exact solution (METHOD.md",
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
    out += bem_section()
    with open(os.path.join(ROOT, "validation", "SPEED_VS_ERROR.md"), "w") as f:
        f.write("\n".join(out))
    print("\n".join(out))


if __name__ == "__main__":
    main()
