#!/usr/bin/python3
"""Table 2 of Kishino (1989) next to gembem's runs.

usage: table2.py RUNDIR_CASE1 [RUNDIR_CASE2 RUNDIR_CASE3 RUNDIR_CASE4]
Prints a Markdown table: e1-e2, the exact rigid solution (computed, docs/method.md section 7), and for
each case the paper's value and gembem's (the stress ratio in RUNDIR/steps.csv at that strain).
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import gembem  # noqa: E402

# Kishino (1989), Table 2: stress ratio at e1 - e2 = 1..5 %, cases 1-4.
PAPER = [[0.5189, 0.5079, 0.4967, 0.4854, 0.4741],
         [0.5187, 0.5076, 0.4965, 0.4852, 0.4739],
         [0.5166, 0.5056, 0.4944, 0.4832, 0.4718],
         [0.5164, 0.5054, 0.4942, 0.4829, 0.4716]]


def exact_ratio(gamma, theta0=math.radians(60)):
    """(K 19)-(K 21), with (K 20) without its spurious factor 2; bisection on theta."""
    s0, c0 = math.sin(theta0), math.cos(theta0)
    lo, hi = 1e-6, theta0
    for _ in range(200):
        th = 0.5 * (lo + hi)
        e1 = -(math.sin(th) - s0) / (1 + s0)
        e2 = -2 * (math.cos(th) - c0) / (1 + 2 * c0)
        lo, hi = (th, hi) if e1 - e2 > gamma else (lo, th)
    R = 2 * math.tan(th) * (1 + math.sin(th)) / (1 + 2 * math.cos(th))
    return (R - 1) / (R + 1)


def ratios(rundir):
    """Stress ratio of the shear stage (stage 2) at e1 - e2 = 1..5 %."""
    s = gembem.Run(rundir).steps
    s = s.select(s["stage"] == 2)
    out = {}
    for k in range(1, 6):
        at = np.flatnonzero(np.abs(s["e1_minus_e2"] - 0.01 * k) < 1e-9)
        if len(at):
            out[k] = float(s["stress_ratio"][at[-1]])
    return out


def main():
    runs = [ratios(d) for d in sys.argv[1:]]
    head = "| e1 - e2 | exact |" + "".join(f" case {c + 1} paper | case {c + 1} gembem |" for c in range(len(runs)))
    print(head)
    print("|" + "---|" * (2 + 2 * len(runs)))
    worst = [0.0] * len(runs)
    for k in range(1, 6):
        line = f"| {k} % | {exact_ratio(0.01 * k):.4f} |"
        for c, r in enumerate(runs):
            line += f" {PAPER[c][k - 1]:.4f} | {r[k]:.4f} |"
            worst[c] = max(worst[c], abs(r[k] - PAPER[c][k - 1]))
        print(line)
    print()
    print("Largest difference from the paper: " +
          ", ".join(f"case {c + 1} {w:.4f}" for c, w in enumerate(worst)))


if __name__ == "__main__":
    main()
