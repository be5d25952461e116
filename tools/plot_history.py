#!/usr/bin/python3
"""Convergence histories from history.csv (a run with `solver: {history: true}`).

    tools/plot_history.py OUT.png STEP LABEL=RUN_DIR [LABEL=RUN_DIR ...] [--accuracy A]

Plots, for load step STEP of each run, the largest fixing force at the start of every iteration
(log scale) against the iteration, all attempts of the step one after the other, then the force
at which it converged (steps.csv), and the accuracy as a line (--accuracy, else the one the step was solved to):
gembem.figures.convergence. Prints per run the iterations and the ratio of successive forces over the last five
iterations (below 1 and falling: a superlinear tail).
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
import gembem  # noqa: E402
from gembem.figures import convergence, iteration_forces  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("step", type=int)
    ap.add_argument("runs", nargs="+", help="LABEL=RUN_DIR")
    ap.add_argument("--accuracy", type=float, default=None)
    a = ap.parse_args()
    labels, runs = zip(*(spec.partition("=")[::2] for spec in a.runs))
    try:
        runs = [gembem.Run(r) for r in runs]
        fig, ax = plt.subplots(figsize=(6, 4))
        convergence(runs, a.step, labels=labels, accuracy=a.accuracy, ax=ax)   # gembem.figures' drawing
    except (OSError, ValueError) as e:
        sys.exit(f"plot_history: {e}")
    for label, run in zip(labels, runs):
        force = iteration_forces(run, a.step)
        tail = [force[k + 1] / force[k] for k in range(max(0, len(force) - 6), len(force) - 1)]
        print(f"{label}: {len(force) - 1} iterations; last ratios " + " ".join(f"{t:.3g}" for t in tail))
    ax.set_ylabel("largest fixing force at its start [dyn]")
    ax.set_title(f"load step {a.step}")
    fig.tight_layout()
    fig.savefig(a.out, dpi=120)


if __name__ == "__main__":
    main()
