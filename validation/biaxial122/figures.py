#!/usr/bin/python3
"""Figures of a 122-disc biaxial run, like Kishino (1989) Figs. 8-17.

usage: figures.py RUNDIR OUTDIR
"""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from biaxial import Biaxial  # noqa: E402  (puts python/ on the path)
import gembem.figures as gf  # noqa: E402


def force_chains(b, step, title, path):
    """gembem.figures.force_chains at a step, framed by the box (steps.csv's width and height)."""
    fig, ax = plt.subplots(figsize=(5.2, 5.2))
    gf.force_chains(b.run, step, ax=ax, title=f"{title} (step {step})\nline width proportional to the normal force")
    ax.title.set_fontsize(10)
    g = b.run.grains(step)
    x0, y0 = np.min(g["x"] - g["r"]), np.min(g["y"] - g["r"])
    ax.set_xlim(x0 - 0.2, x0 + b.steps["width"][step] + 0.2)
    ax.set_ylim(y0 - 0.2, y0 + b.steps["height"][step] + 0.2)
    ax.set_xlabel("")
    ax.set_ylabel("")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def rose(b, steps, labels, column, title, path):
    """gembem.figures.rose (contacts/rose_NNNNNN.csv, 36 sectors, from the grains' side: a
    grain-grain contact in n and -n, a grain-wall contact once, in per cent) at two steps."""
    fig = plt.figure(figsize=(8, 4))
    for k, (step, label) in enumerate(zip(steps, labels)):
        ax = fig.add_subplot(1, 2, k + 1, projection="polar")
        gf.rose(b.run, step, column, ax=ax)
        ax.set_title(f"{label} (step {step})", fontsize=10)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    b, out = Biaxial(sys.argv[1]), sys.argv[2]
    os.makedirs(out, exist_ok=True)
    s0, pk, steps, m = b.shear_start, b.peak_step, b.shear, b.micro
    x = b.gamma[steps]
    force_chains(b, s0, "Contact forces, initial state", f"{out}/fig08_forces_initial.png")
    force_chains(b, pk, "Contact forces, peak state", f"{out}/fig10_forces_peak.png")

    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.plot(x, b.ratio[steps], "k-", label="s1/s2")
    ax.plot([b.gamma[pk]], [b.ratio[pk]], "ko", label="peak")
    ax.set_xlabel("e1 - e2 [%]")
    ax.set_ylabel("s1 / s2")
    ax2 = ax.twinx()
    ax2.plot(x, b.ev[steps], "b--", label="ev")
    ax2.set_ylabel("volumetric strain ev [%] (compression +)", color="b")
    ax.set_title("Stress ratio and volumetric strain (cf. Fig. 9)")
    ax.legend(loc="upper left")
    fig.tight_layout()
    fig.savefig(f"{out}/fig09_stress_strain.png", dpi=110)
    plt.close(fig)

    rose(b, [s0, pk], ["initial", "peak"], "count", "Contact normals, % (cf. Fig. 11)", f"{out}/fig11_rose_normals.png")
    rose(b, [s0, pk], ["initial", "peak"], "energy", "Elastic energy by contact direction, % (cf. Fig. 12)",
         f"{out}/fig12_rose_energy.png")

    for key, name, fname, fig_no in (("C", "coordination tensor", "fig13_fabric.png", 13),
                                     ("E", "elastic energy tensor [dyn/cm]", "fig14_energy_tensor.png", 14)):
        fig, ax = plt.subplots(figsize=(6, 4))
        ax.plot(x, m[f"{key}_yy"][steps], "k-", label=f"{key}1 (vertical)")
        ax.plot(x, m[f"{key}_xx"][steps], "k--", label=f"{key}2 (horizontal)")
        ax.axvline(b.gamma[pk], color="0.7", lw=0.8)
        ax.set_xlabel("e1 - e2 [%]")
        ax.set_ylabel(name)
        ax.legend()
        ax.set_title(f"Principal values of the {name.split(' [')[0]} (cf. Fig. {fig_no})")
        fig.tight_layout()
        fig.savefig(f"{out}/{fname}", dpi=110)
        plt.close(fig)

    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(x, (m["work"][steps] - m["work"][s0]) / m["area"][steps], "k-", label="W")
    ax.plot(x, (m["dissipation"][steps] - m["dissipation"][s0]) / m["area"][steps], "k--", label="D")
    ax.set_xlabel("e1 - e2 [%]")
    ax.set_ylabel("energy per unit area [dyn/cm]")
    ax.legend()
    ax.set_title("External work and dissipation (cf. Fig. 15)")
    fig.tight_layout()
    fig.savefig(f"{out}/fig15_work_dissipation.png", dpi=110)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(6, 4))
    ax.bar(steps[1:] - s0, 100 * m["P_max"][steps[1:]], color="0.4")
    ax.set_xlabel("shear step")
    ax.set_ylabel("P_max [%]")
    ax.set_title("Largest single-contact share of a step's dissipation (cf. Fig. 16)")
    fig.tight_layout()
    fig.savefig(f"{out}/fig16_pmax.png", dpi=110)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(6, 4.5))
    for k, label in ((1, "step 1"), (5, "step 5"), (pk - s0 + 1, "just after the peak")):
        step = s0 + k
        if step >= b.steps.nrows:
            continue
        d = np.sort(b.run.contacts(step)["dissipation"])[::-1]
        p = d[:20] / m["dissipation_step"][step]
        p = p[d[:20] > 0]
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
