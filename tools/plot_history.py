#!/usr/bin/python3
"""Convergence histories from history.csv (a run with `solver: {history: true}`).

    tools/plot_history.py OUT.png STEP LABEL=RUN_DIR [LABEL=RUN_DIR ...] [--accuracy A]

Plots, for load step STEP of each run, the largest fixing force at the start of every iteration
(log scale) against the iteration, all attempts of the step one after the other, then the force
at which it converged (steps.csv), and the accuracy as a line. Prints per run the iterations and the ratio of successive forces over the last five
iterations (below 1 and falling: a superlinear tail).
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("step", type=int)
    ap.add_argument("runs", nargs="+", help="LABEL=RUN_DIR")
    ap.add_argument("--accuracy", type=float, default=None)
    a = ap.parse_args()
    fig, ax = plt.subplots(figsize=(6, 4))
    for spec in a.runs:
        label, _, run = spec.partition("=")
        path = os.path.join(run, "history.csv")
        try:
            with open(path) as f:
                rows = [r for r in csv.DictReader(f) if int(r["step"]) == a.step]
        except OSError as e:
            sys.exit(f"plot_history: {e}")
        if not rows:
            sys.exit(f"plot_history: {path} has no row for step {a.step}")
        force = [float(r["max_fixing_force"]) for r in rows]
        with open(os.path.join(run, "steps.csv")) as f:  # the converged step's force: the last point
            done = [float(r["max_fixing_force"]) for r in csv.DictReader(f) if int(r["step"]) == a.step]
        force += done
        ax.semilogy(range(1, len(force) + 1), force, marker="o", ms=3, label=f"{label} ({len(rows)} iterations)")
        tail = [force[k + 1] / force[k] for k in range(max(0, len(force) - 6), len(force) - 1)]
        print(f"{label}: {len(rows)} iterations; last ratios " + " ".join(f"{t:.3g}" for t in tail))
    if a.accuracy:
        ax.axhline(a.accuracy, color="k", lw=0.8, ls="--", label=f"accuracy {a.accuracy:g}")
    ax.set_xlabel("iteration of the load step")
    ax.set_ylabel("largest fixing force at its start [dyn]")
    ax.set_title(f"load step {a.step}")
    ax.legend()
    fig.tight_layout()
    fig.savefig(a.out, dpi=120)


if __name__ == "__main__":
    main()
