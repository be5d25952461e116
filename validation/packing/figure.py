#!/usr/bin/python3
"""Draws a gembem pack directory: its grains, and the host's boundary particles if any.

  figure.py PACKDIR OUT.png
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import gembem  # noqa: E402

d, out = sys.argv[1], sys.argv[2]
state = gembem.read_state(d)
fig, ax = plt.subplots(figsize=(6, 5))
for x, y, r in zip(state.grains["x"], state.grains["y"], state.grains["r"]):
    ax.add_patch(plt.Circle((x, y), r, fill=False, lw=0.6))
if state.host_particles is not None:
    ax.plot(state.host_particles["x"], state.host_particles["y"], "r.", ms=2)
ax.set_aspect("equal")
ax.autoscale()
ax.set_xlabel("x [cm]")
ax.set_ylabel("y [cm]")
fig.tight_layout()
fig.savefig(out, dpi=90)
