#!/usr/bin/python3
"""The 122-disc biaxial test with and without rolling resistance: principal stress ratio s1/s2 and
volumetric strain against the shear strain e1 - e2, every packing thin and the median over the
packings thick, next to Kishino's (1989) peak (about 1.7 near 1.8 %). Prints per set the statistics of README.md's
section on rolling resistance: peak s1/s2, the shear strain at the peak, the volumetric strain
at the peak and at 5 %, the packings that end dilated (ev at 5 % below 0) and the dilation after
the most compacted state (largest ev minus ev at 5 %).

usage: rolling_figure.py OUT.png DIR=LABEL ...
DIR: a workflow's out directory (runs/biaxial122_base, runs/biaxial122_rolling, README.md) with
seedN/run/ run directories; LABEL its name in the legend.
"""
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from biaxial import Biaxial  # noqa: E402


def curves(d):
    """Per completed packing (status.yaml): shear strain [%], s1/s2 and ev [%] over the shear stage."""
    out = []
    for run in sorted(glob.glob(os.path.join(d, "seed*", "run"))):
        with open(os.path.join(os.path.dirname(run), "status.yaml")) as f:
            if "status: completed" not in f.read():
                continue
        b = Biaxial(run)
        out.append(np.column_stack([b.gamma[b.shear], b.ratio[b.shear], b.ev[b.shear]]))
    return out


def summary(label, runs):
    peak = [c[np.argmax(c[1:, 1]) + 1] for c in runs]
    ms = lambda v: f"{np.mean(v):.3f} +- {np.std(v, ddof=1):.3f} (median {np.median(v):.3f})"
    print(f"{label}: {len(runs)} packings")
    print(f"  peak s1/s2            {ms([p[1] for p in peak])}")
    print(f"  e1-e2 at peak [%]     {ms([p[0] for p in peak])}")
    print(f"  ev at peak [%]        {ms([p[2] for p in peak])}")
    print(f"  ev at 5 % [%]         {ms([c[-1, 2] for c in runs])}")
    print(f"  ended dilated         {sum(c[-1, 2] < 0 for c in runs)} of {len(runs)}")
    print(f"  dilation after the most compacted state [%] {ms([c[:, 2].max() - c[-1, 2] for c in runs])}")


def main():
    if len(sys.argv) < 3 or any("=" not in a for a in sys.argv[2:]):
        sys.exit(__doc__)
    colors = ("tab:blue", "tab:red", "tab:green", "tab:purple")
    sets = [(a.split("=", 1)[1], curves(a.split("=", 1)[0]), colors[k % 4]) for k, a in enumerate(sys.argv[2:])]
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for label, runs, color in sets:
        summary(label, runs)
        n = min(len(c) for c in runs)
        for c in runs:
            ax[0].plot(c[:, 0], c[:, 1], color=color, lw=0.5, alpha=0.4)
            ax[1].plot(c[:, 0], c[:, 2], color=color, lw=0.5, alpha=0.4)
        mid = np.median([c[:n] for c in runs], axis=0)
        ax[0].plot(mid[:, 0], mid[:, 1], color=color, lw=2, label=f"{label}: median of {len(runs)} packings")
        ax[1].plot(mid[:, 0], mid[:, 2], color=color, lw=2, label=f"{label}: median of {len(runs)} packings")
    ax[0].plot([1.8], [1.7], "k*", ms=12, label="Kishino (1989): peak about 1.7 near 1.8 %")
    ax[0].set(xlabel="e1 - e2 [%]", ylabel="s1 / s2", title="principal stress ratio")
    ax[1].set(xlabel="e1 - e2 [%]", ylabel="ev [%] (compression positive)", title="volumetric strain")
    ax[1].axhline(0, color="k", lw=0.5)
    for a in ax:
        a.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(sys.argv[1], dpi=120)


if __name__ == "__main__":
    main()
