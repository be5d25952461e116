#!/usr/bin/python3
"""Statistics of several 122-disc biaxial runs next to Kishino (1989): peak s1/s2, shear strain at
the peak, volumetric response, largest energy-balance error.

usage: stats.py RUNDIR ...
"""
import csv
import math
import os
import statistics
import sys

from biaxial import Run


def main():
    rows = []
    print("| run | porosity at shear start | peak s1/s2 | e1-e2 at peak [%] | ev at peak [%] | ev at 5 % [%] | "
          "paper's balance: max \\|W-D-dE\\|/W in shear | iteration's books: max \\|W_it-D-L-dE\\|/W_it | "
          "iterations per shear step | seconds |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for d in sys.argv[1:]:
        r = Run(d)
        pk = r.steps[r.peak_step]
        ev_pk = r.shear_ev(pk)
        ev_end = r.shear_ev(r.shear[-1])
        bal = max(abs(r.balance_from_shear_start(int(s["step"]))[0]) for s in r.shear[1:])
        books = max(abs(float(m["balance_iter"])) / (float(m["work_walls_iter"]) + float(m["work_body"]))
                    for m in r.micro[1:])
        it = statistics.mean(int(s["iterations"]) for s in r.shear[1:])
        secs = sum(float(s["seconds"]) for s in r.steps)
        area = float(r.shear[0]["width"]) * float(r.shear[0]["height"])
        with open(os.path.join(d, "contacts", f"grains_{r.shear_start:06d}.csv")) as f:
            solid = sum(math.pi * float(g["r"]) ** 2 for g in csv.DictReader(f))
        por = 1 - solid / area
        rows.append((Run.principal_ratio(pk), r.shear_strain(pk), ev_pk, ev_end, bal, books))
        print(f"| {d.split('/')[-2]} | {por:.3f} | {Run.principal_ratio(pk):.3f} | {r.shear_strain(pk):.2f} | {ev_pk:.2f} | "
              f"{ev_end:.2f} | {100 * bal:.1f} % | {100 * books:.2f} % | {it:.0f} | {secs:.1f} |")
    if len(rows) > 1:
        cols = list(zip(*rows))
        f = lambda v: f"{statistics.mean(v):.3f} +- {statistics.stdev(v):.3f}"
        print(f"| mean +- sd | | {f(cols[0])} | {f(cols[1])} | {f(cols[2])} | {f(cols[3])} | {100 * max(cols[4]):.1f} % (max) | {100 * max(cols[5]):.2f} % (max) | | |")
    print("| Kishino (1989) | 0.260 (initial) | about 1.7 | about 1.8 | | dilatant | a few % | | | |")


if __name__ == "__main__":
    main()
