#!/usr/bin/python3
"""A figure like Kishino (1989) Fig. 7: stress ratio against shear strain for the three discs,
case 1 constants, phi = 25 deg between discs and phi' = 0, 5, 10, 15 deg against the walls, with
the rigid exact solution dashed.

usage: fig7.py OUT.png RUNDIR_0 RUNDIR_5 RUNDIR_10 RUNDIR_15
"""
import csv
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

from table2 import exact_ratio


def curve(rundir):
    xs, ys = [], []
    with open(f"{rundir}/steps.csv") as f:
        for row in csv.DictReader(f):
            if row["stage"] == "2" or row["step"] == "10":
                xs.append(100 * max(0.0, float(row["e1_minus_e2"])))
                ys.append(float(row["stress_ratio"]))
    return xs, ys


def main():
    out, runs = sys.argv[1], sys.argv[2:]
    fig, ax = plt.subplots(figsize=(6, 4.2))
    for phi_w, d in zip((0, 5, 10, 15), runs):
        x, y = curve(d)
        ax.plot(x, y, label=f"phi' = {phi_w} deg")
    g = [0.0] + [0.05 * k for k in range(1, 101)]
    ax.plot(g, [exact_ratio(max(v, 1e-9) / 100) for v in g], "k--", label="exact (rigid, frictionless)")
    ax.set_xlabel("e1 - e2 [%]")
    ax.set_ylabel("(s1 - s2) / (s1 + s2)")
    ax.set_xlim(0, 5)
    ax.set_ylim(0, 1.1)
    ax.set_title("Three discs, phi = 25 deg (cf. Kishino 1989, Fig. 7)")
    ax.legend(loc="lower right")
    fig.tight_layout()
    fig.savefig(out, dpi=120)


if __name__ == "__main__":
    main()
