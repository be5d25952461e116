#!/usr/bin/python3
"""Figures of a cavity packing run (like the hybrid paper's Fig. 2): the grains at the start
(dashed) and at equilibrium, the boundary particles, and the grains' displacements; and the host's
cavity, deformed (displacements magnified).

usage: figures.py RUNDIR OUT_PREFIX TITLE
"""
import csv
import math
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.patches import Circle, Wedge


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def main():
    run, out, title = sys.argv[1], sys.argv[2], sys.argv[3]
    g0 = rows(f"{run}/contacts/grains_000000.csv")
    g1 = rows(f"{run}/contacts/grains_000001.csv")
    bp = rows(f"{run}/host_particles.csv")
    fig, ax = plt.subplots(figsize=(6, 6))
    for p in bp:  # half-discs bulging into the cavity, moved with their element
        x, y = float(p["x"]) + float(p["ux"]), float(p["y"]) + float(p["uy"])
        a = math.degrees(math.atan2(float(p["ny"]), float(p["nx"])))
        ax.add_patch(Wedge((x, y), float(p["r"]), a - 90, a + 90, facecolor="0.85", edgecolor="0.4", lw=0.6))
    for a, b in zip(g0, g1):
        ax.add_patch(Circle((float(a["x"]), float(a["y"])), float(a["r"]), fill=False, ls="--", lw=0.6, color="0.6"))
        ax.add_patch(Circle((float(b["x"]), float(b["y"])), float(b["r"]), fill=False, lw=1.0, color="k"))
    ax.quiver([float(a["x"]) for a in g0], [float(a["y"]) for a in g0],
              [float(b["x"]) - float(a["x"]) for a, b in zip(g0, g1)],
              [float(b["y"]) - float(a["y"]) for a, b in zip(g0, g1)],
              angles="xy", scale_units="xy", scale=1, color="r", width=0.004)
    ax.set_xlim(-2.8, 2.8)
    ax.set_ylim(-2.8, 2.8)
    ax.set_aspect("equal")
    ax.set_title(f"{title}\ndashed: placed, solid: equilibrium, red: displacement")
    fig.tight_layout()
    fig.savefig(f"{out}_grains.png", dpi=110)
    plt.close(fig)

    hb = [r for r in rows(f"{run}/host_boundary.csv") if r["group"] == "cavity"]
    umax = max(math.hypot(float(r["ux"]), float(r["uy"])) for r in hb)
    mag = 0.3 / umax if umax > 0 else 1.0
    fig, ax = plt.subplots(figsize=(6, 6))
    order = sorted(hb, key=lambda r: math.atan2(float(r["y"]), float(r["x"])))
    xs = [float(r["x"]) for r in order] + [float(order[0]["x"])]
    ys = [float(r["y"]) for r in order] + [float(order[0]["y"])]
    ax.plot(xs, ys, "k--", lw=0.8, label="cavity at rest (element midpoints)")
    xd = [float(r["x"]) + mag * float(r["ux"]) for r in order]
    yd = [float(r["y"]) + mag * float(r["uy"]) for r in order]
    ax.plot(xd + xd[:1], yd + yd[:1], "b-", lw=1.2, label=f"deformed, displacements x {mag:.3g}")
    ax.set_aspect("equal")
    ax.legend(loc="lower left", fontsize=8)
    ax.set_title(f"The host's cavity (largest displacement {umax:.3g} cm)")
    fig.tight_layout()
    fig.savefig(f"{out}_cavity.png", dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    main()
