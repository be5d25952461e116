#!/usr/bin/python3
"""Compares two gembem runs of one scene made with different linear solvers (tests/petsc):
  compare_runs.py FIRST_SOLVE_REF FIRST_SOLVE RUN_REF RUN SOLVE_TOL STRESS_TOL STRAIN_TOL [HOST_TOL]
FIRST_SOLVE*: the first linear solution of each run (GB_DUMP_FIRST_SOLVE), equal to SOLVE_TOL
relative (2-norm). RUN*: run directories; every step of steps.csv must be in both, with s1, s2 within
STRESS_TOL and e1, e2 within STRAIN_TOL (absolute; columns that are nan in both are skipped), and,
with HOST_TOL, host_steps.csv's displacements and forces within HOST_TOL times the largest of each
column. Prints the differences found; exit 1 if one is above its tolerance."""
import csv
import math
import os
import sys


def vector(path):
    with open(path) as f:
        return [float(line) for line in f]


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def main(argv):
    ref_x, x, ref_run, run = argv[1:5]
    solve_tol, stress_tol, strain_tol = (float(v) for v in argv[5:8])
    host_tol = float(argv[8]) if len(argv) > 8 else None
    ok = True
    a, b = vector(ref_x), vector(x)
    if len(a) != len(b):
        print(f"FAIL first solve: {len(a)} unknowns against {len(b)}")
        return 1
    diff = math.sqrt(sum((u - v) ** 2 for u, v in zip(a, b))) / math.sqrt(sum(u * u for u in a))
    ok &= diff <= solve_tol
    print(f"{'ok  ' if diff <= solve_tol else 'FAIL'} first solve: {len(a)} unknowns, relative difference "
          f"{diff:.3e} (tolerance {solve_tol:g})")
    ra, rb = rows(os.path.join(ref_run, "steps.csv")), rows(os.path.join(run, "steps.csv"))
    if len(ra) != len(rb):
        print(f"FAIL steps: {len(ra)} rows against {len(rb)}")
        return 1
    worst = {"s1": 0.0, "s2": 0.0, "e1": 0.0, "e2": 0.0}
    for p, q in zip(ra, rb):
        for key in worst:
            u, v = float(p[key]), float(q[key])
            if math.isnan(u) and math.isnan(v):
                continue
            d = abs(u - v)
            worst[key] = max(worst[key], d) if d == d else math.inf
    for key, d in worst.items():
        tol = stress_tol if key[0] == "s" else strain_tol
        ok &= d <= tol
        print(f"{'ok  ' if d <= tol else 'FAIL'} steps.csv {key}: largest difference {d:.3e} (tolerance {tol:g})")
    print("     iterations per step: " + " ".join(f"{p['iterations']}/{q['iterations']}" for p, q in zip(ra, rb)))
    if host_tol is not None:
        ha, hb = rows(os.path.join(ref_run, "host_steps.csv")), rows(os.path.join(run, "host_steps.csv"))
        if len(ha) != len(hb):
            print(f"FAIL host_steps: {len(ha)} rows against {len(hb)}")
            return 1
        for key in ("ux", "uy", "fx", "fy"):
            scale = max(abs(float(p[key])) for p in ha)
            d = max(abs(float(p[key]) - float(q[key])) for p, q in zip(ha, hb))
            ok &= d <= host_tol * scale
            print(f"{'ok  ' if d <= host_tol * scale else 'FAIL'} host_steps.csv {key}: largest difference {d:.3e} "
                  f"(tolerance {host_tol:g} x {scale:.3e})")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
