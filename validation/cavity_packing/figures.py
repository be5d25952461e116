#!/usr/bin/python3
"""Figures of a cavity packing run (like the hybrid paper's Fig. 2): the grains at the start
(dashed) and at equilibrium, the boundary particles, and the grains' displacements; and the host's
cavity, deformed (displacements magnified).

usage: figures.py RUNDIR OUT_PREFIX TITLE
"""
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.patches import Circle, Wedge  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import gembem  # noqa: E402


def main():
    run, out, title = gembem.Run(sys.argv[1]), sys.argv[2], sys.argv[3]
    g0, g1, bp = run.grains(0), run.grains(1), run.host_particles
    fig, ax = plt.subplots(figsize=(6, 6))
    for k in range(bp.nrows):  # half-discs bulging into the cavity, moved with their element
        x, y = bp["x"][k] + bp["ux"][k], bp["y"][k] + bp["uy"][k]
        a = math.degrees(math.atan2(bp["ny"][k], bp["nx"][k]))
        ax.add_patch(Wedge((x, y), bp["r"][k], a - 90, a + 90, facecolor="0.85", edgecolor="0.4", lw=0.6))
    for k in range(g0.nrows):
        ax.add_patch(Circle((g0["x"][k], g0["y"][k]), g0["r"][k], fill=False, ls="--", lw=0.6, color="0.6"))
        ax.add_patch(Circle((g1["x"][k], g1["y"][k]), g1["r"][k], fill=False, lw=1.0, color="k"))
    ax.quiver(g0["x"], g0["y"], g1["x"] - g0["x"], g1["y"] - g0["y"],
              angles="xy", scale_units="xy", scale=1, color="r", width=0.004)
    ax.set_xlim(-2.8, 2.8)
    ax.set_ylim(-2.8, 2.8)
    ax.set_aspect("equal")
    ax.set_title(f"{title}\ndashed: placed, solid: equilibrium, red: displacement")
    fig.tight_layout()
    fig.savefig(f"{out}_grains.png", dpi=110)
    plt.close(fig)

    hb = run.host_boundary.select(run.host_boundary["group"] == "cavity")
    umax = float(np.max(np.hypot(hb["ux"], hb["uy"])))
    mag = 0.3 / umax if umax > 0 else 1.0
    fig, ax = plt.subplots(figsize=(6, 6))
    order = hb.select(np.argsort(np.arctan2(hb["y"], hb["x"]), kind="stable"))
    loop = np.r_[np.arange(order.nrows), 0]
    ax.plot(order["x"][loop], order["y"][loop], "k--", lw=0.8, label="cavity at rest (element midpoints)")
    xd, yd = order["x"] + mag * order["ux"], order["y"] + mag * order["uy"]
    ax.plot(xd[loop], yd[loop], "b-", lw=1.2, label=f"deformed, displacements x {mag:.3g}")
    ax.set_aspect("equal")
    ax.legend(loc="lower left", fontsize=8)
    ax.set_title(f"The host's cavity (largest displacement {umax:.3g} cm)")
    fig.tight_layout()
    fig.savefig(f"{out}_cavity.png", dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    main()
