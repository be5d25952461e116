#!/usr/bin/python3
"""Draws a gembem pack directory: its grains, and the host's boundary particles if any.

  figure.py PACKDIR OUT.png
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

d, out = sys.argv[1], sys.argv[2]
fig, ax = plt.subplots(figsize=(6, 5))
for r in csv.DictReader(open(os.path.join(d, "state_grains.csv"))):
    ax.add_patch(plt.Circle((float(r["x"]), float(r["y"])), float(r["r"]), fill=False, lw=0.6))
host = os.path.join(d, "state_host.csv")
if os.path.exists(host):
    h = list(csv.DictReader(open(host)))
    ax.plot([float(r["x"]) for r in h], [float(r["y"]) for r in h], "r.", ms=2)
ax.set_aspect("equal")
ax.autoscale()
ax.set_xlabel("x [cm]")
ax.set_ylabel("y [cm]")
fig.tight_layout()
fig.savefig(out, dpi=90)
