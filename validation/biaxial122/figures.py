#!/usr/bin/python3
"""Figures of a 122-disc biaxial run, like Kishino (1989) Figs. 8-17.

usage: figures.py RUNDIR OUTDIR
"""
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import LineCollection
from matplotlib.patches import Circle

from biaxial import Run


def force_chains(run, step, title, path):
    fig, ax = plt.subplots(figsize=(5.2, 5.2))
    for g in run.grains(step):
        ax.add_patch(Circle((float(g["x"]), float(g["y"])), float(g["r"]), fill=False, lw=0.5, color="0.5"))
    cs = run.contacts(step)
    pmax = max(float(c["pn"]) for c in cs)
    segs = [((float(c["xi"]), float(c["yi"])), (float(c["xj"]), float(c["yj"]))) for c in cs]
    widths = [6 * float(c["pn"]) / pmax for c in cs]
    ax.add_collection(LineCollection(segs, linewidths=widths, colors="k"))
    row = run.steps[step]
    W, H = float(row["width"]), float(row["height"])
    gs = run.grains(step)
    x0 = min(float(g["x"]) - float(g["r"]) for g in gs)
    y0 = min(float(g["y"]) - float(g["r"]) for g in gs)
    ax.set_xlim(x0 - 0.2, x0 + W + 0.2)
    ax.set_ylim(y0 - 0.2, y0 + H + 0.2)
    ax.set_aspect("equal")
    ax.set_title(f"{title} (step {step})\nline width proportional to the normal force", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def rose(run, steps, labels, column, title, path):
    """Contact normals by direction from gembem's rose_NNNNNN.csv (36 sectors, from the grains'
    side: a grain-grain contact in n and -n, a grain-wall contact once), in per cent."""
    fig = plt.figure(figsize=(8, 4))
    for k, (step, label) in enumerate(zip(steps, labels)):
        rows = run.rose(step)
        vals = [float(r[column]) for r in rows]
        total = sum(vals)
        ax = fig.add_subplot(1, 2, k + 1, projection="polar")
        th = [math.radians(float(r["from_deg"]) + 5) for r in rows]
        ax.bar(th, [100 * v / total for v in vals], width=math.radians(10), edgecolor="k", color="0.8")
        ax.set_title(f"{label} (step {step})", fontsize=10)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    run, out = Run(sys.argv[1]), sys.argv[2]
    os.makedirs(out, exist_ok=True)
    s0, pk = run.shear_start, run.peak_step
    x = [run.shear_strain(r) for r in run.shear]
    steps = [int(r["step"]) for r in run.shear]
    force_chains(run, s0, "Contact forces, initial state", f"{out}/fig08_forces_initial.png")
    force_chains(run, pk, "Contact forces, peak state", f"{out}/fig10_forces_peak.png")

    fig, ax = plt.subplots(figsize=(6, 4.5))
    ratio = [run.principal_ratio(r) for r in run.shear]
    ax.plot(x, ratio, "k-", label="s1/s2")
    ax.plot([run.shear_strain(run.steps[pk])], [run.principal_ratio(run.steps[pk])], "ko", label="peak")
    ax.set_xlabel("e1 - e2 [%]")
    ax.set_ylabel("s1 / s2")
    ax2 = ax.twinx()
    ax2.plot(x, [run.shear_ev(r) for r in run.shear], "b--", label="ev")
    ax2.set_ylabel("volumetric strain ev [%] (compression +)", color="b")
    ax.set_title("Stress ratio and volumetric strain (cf. Fig. 9)")
    ax.legend(loc="upper left")
    fig.tight_layout()
    fig.savefig(f"{out}/fig09_stress_strain.png", dpi=110)
    plt.close(fig)

    rose(run, [s0, pk], ["initial", "peak"], "count", "Contact normals, % (cf. Fig. 11)", f"{out}/fig11_rose_normals.png")
    rose(run, [s0, pk], ["initial", "peak"], "energy", "Elastic energy by contact direction, % (cf. Fig. 12)",
         f"{out}/fig12_rose_energy.png")

    for key, name, fname, fig_no in (("C", "coordination tensor", "fig13_fabric.png", 13),
                                     ("E", "elastic energy tensor [dyn/cm]", "fig14_energy_tensor.png", 14)):
        fig, ax = plt.subplots(figsize=(6, 4))
        m = [run.micro_at(s) for s in steps]
        ax.plot(x, [float(r[f"{key}_yy"]) for r in m], "k-", label=f"{key}1 (vertical)")
        ax.plot(x, [float(r[f"{key}_xx"]) for r in m], "k--", label=f"{key}2 (horizontal)")
        ax.axvline(run.shear_strain(run.steps[pk]), color="0.7", lw=0.8)
        ax.set_xlabel("e1 - e2 [%]")
        ax.set_ylabel(name)
        ax.legend()
        ax.set_title(f"Principal values of the {name.split(' [')[0]} (cf. Fig. {fig_no})")
        fig.tight_layout()
        fig.savefig(f"{out}/{fname}", dpi=110)
        plt.close(fig)

    fig, ax = plt.subplots(figsize=(6, 4))
    a = run.micro_at(s0)
    m = [run.micro_at(s) for s in steps]
    ax.plot(x, [(float(r["work"]) - float(a["work"])) / float(r["area"]) for r in m], "k-", label="W")
    ax.plot(x, [(float(r["dissipation"]) - float(a["dissipation"])) / float(r["area"]) for r in m], "k--", label="D")
    ax.set_xlabel("e1 - e2 [%]")
    ax.set_ylabel("energy per unit area [dyn/cm]")
    ax.legend()
    ax.set_title("External work and dissipation (cf. Fig. 15)")
    fig.tight_layout()
    fig.savefig(f"{out}/fig15_work_dissipation.png", dpi=110)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(6, 4))
    ax.bar([s - s0 for s in steps[1:]], [100 * float(run.micro_at(s)["P_max"]) for s in steps[1:]], color="0.4")
    ax.set_xlabel("shear step")
    ax.set_ylabel("P_max [%]")
    ax.set_title("Largest single-contact share of a step's dissipation (cf. Fig. 16)")
    fig.tight_layout()
    fig.savefig(f"{out}/fig16_pmax.png", dpi=110)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(6, 4.5))
    for k, label in ((1, "step 1"), (5, "step 5"), (pk - s0 + 1, "just after the peak")):
        step = s0 + k
        if step >= len(run.steps):
            continue
        d = sorted((float(c["dissipation"]) for c in run.contacts(step)), reverse=True)
        total = float(run.micro_at(step)["dissipation_step"])
        p = [v / total for v in d[:20] if v > 0]
        ax.loglog(p, range(1, len(p) + 1), "o-", label=f"{label} (shear step {k})")
    ax.set_xlabel("P (share of the step's dissipation)")
    ax.set_ylabel("N(>= P)")
    ax.legend()
    ax.set_title("Distribution of dissipation, top 20 contacts (cf. Fig. 17)")
    fig.tight_layout()
    fig.savefig(f"{out}/fig17_dissipation_distribution.png", dpi=110)
    plt.close(fig)
    print(f"figures in {out}: shear from step {s0}, peak at step {pk}")


if __name__ == "__main__":
    main()
