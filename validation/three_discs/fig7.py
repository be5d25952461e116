#!/usr/bin/python3
"""A figure like Kishino (1989) Fig. 7: stress ratio against shear strain for the three discs,
case 1 constants, phi = 25 deg between discs and phi' = 0, 5, 10, 15 deg against the walls, with
the rigid exact solution dashed.

usage: fig7.py OUT.png RUNDIR_0 RUNDIR_5 RUNDIR_10 RUNDIR_15
"""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from table2 import exact_ratio, gembem  # noqa: E402  (table2 puts python/ on the path)


def curve(rundir):
    """The shear stage (stage 2) and the state it starts from (step 10): e1 - e2 [%], stress ratio."""
    s = gembem.Run(rundir).steps
    s = s.select((s["stage"] == 2) | (s["step"] == 10))
    return 100 * np.maximum(0.0, s["e1_minus_e2"]), s["stress_ratio"]


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
