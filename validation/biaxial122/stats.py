#!/usr/bin/python3
"""Statistics of several 122-disc biaxial runs next to Kishino (1989): peak s1/s2, shear strain at
the peak, volumetric response, largest energy-balance error.

usage: stats.py RUNDIR ...            the table of those runs
       stats.py --results results.csv the table of the workflow's aggregated measures (Snakefile)
The workflow measures each run with measures() and gathers them in results.csv.
"""
import statistics
import sys

import numpy as np

from biaxial import Biaxial, gembem

HEAD = ("| run | porosity at shear start | peak s1/s2 | e1-e2 at peak [%] | ev at peak [%] | ev at 5 % [%] | "
        "paper's balance: max \\|W-D-dE\\|/W in shear | iteration's books: max \\|W_it-D-L-dE\\|/W_it | "
        "iterations per shear step | seconds |\n|---|---|---|---|---|---|---|---|---|---|")
KEYS = ("porosity", "peak_ratio", "peak_strain", "ev_peak", "ev_end", "balance", "books", "iterations", "seconds")
PAPER = "| Kishino (1989) | 0.260 (initial) | about 1.7 | about 1.8 | | dilatant | a few % | | | |"


def measures(d):
    """One run's numbers: the shear stage's peak, volumetric strains, energy balances, cost."""
    b = Biaxial(d)
    s, m, pk, start = b.steps, b.micro, b.peak_step, b.shear_start
    g = b.run.grains(start)
    shear = b.shear[1:]
    return {
        "porosity": 1 - float(np.sum(np.pi * g["r"] ** 2)) / float(s["width"][start] * s["height"][start]),
        "peak_ratio": float(b.ratio[pk]),
        "peak_strain": float(b.gamma[pk]),
        "ev_peak": float(b.ev[pk]),
        "ev_end": float(b.ev[b.shear[-1]]),
        "balance": max(abs(b.balance_from_shear_start(int(k))[0]) for k in shear),
        "books": float(np.max(np.abs(m["balance_iter"][1:]) / (m["work_walls_iter"][1:] + m["work_body"][1:]))),
        "iterations": float(np.mean(s["iterations"][shear])),
        "seconds": float(np.sum(s["seconds"])),
    }


def table(rows):
    """The markdown table: rows of (label, measures or a status string for a run that is missing)."""
    out = [HEAD]
    done = [m for _, m in rows if isinstance(m, dict)]
    for label, m in rows:
        if not isinstance(m, dict):
            out.append(f"| {label} | {m} | | | | | | | | |")
            continue
        out.append(f"| {label} | {m['porosity']:.3f} | {m['peak_ratio']:.3f} | {m['peak_strain']:.2f} | "
                   f"{m['ev_peak']:.2f} | {m['ev_end']:.2f} | {100 * m['balance']:.1f} % | "
                   f"{100 * m['books']:.2f} % | {m['iterations']:.0f} | {m['seconds']:.1f} |")
    if len(done) > 1:
        f = lambda k: f"{statistics.mean(m[k] for m in done):.3f} +- {statistics.stdev(m[k] for m in done):.3f}"
        worst = lambda k: max(m[k] for m in done)
        out.append(f"| mean +- sd | | {f('peak_ratio')} | {f('peak_strain')} | {f('ev_peak')} | {f('ev_end')} | "
                   f"{100 * worst('balance'):.1f} % (max) | {100 * worst('books'):.2f} % (max) | | |")
    out.append(PAPER)
    return "\n".join(out)


def results_rows(path):
    """(label, measures or status) per case of the workflow's results.csv."""
    t = gembem.read_csv(path)
    return [(str(t["case"][i]), {k: float(t[k][i]) for k in KEYS} if t["status"][i] == "completed"
             else str(t["status"][i])) for i in range(t.nrows)]


def main():
    if sys.argv[1:2] == ["--results"]:
        rows = results_rows(sys.argv[2])
    else:
        rows = [(d.rstrip("/").split("/")[-2], measures(d)) for d in sys.argv[1:]]
    print(table(rows))


if __name__ == "__main__":
    main()
