#!/usr/bin/python3
"""The solid fraction of a packing away from its walls and free surface: the share of a grid of
points in a window that lies inside a disc (state_grains.csv of a gembem pack directory).

  bulk.py PACKDIR X0 X1 Y0 Y1 [N]      the window [X0, X1] x [Y0, Y1], N x N points (default 400)
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import gembem  # noqa: E402

d, x0, x1, y0, y1 = sys.argv[1], *map(float, sys.argv[2:6])
n = int(sys.argv[6]) if len(sys.argv) > 6 else 400
g = gembem.read_state(d).grains
xs, ys = np.meshgrid(np.linspace(x0, x1, n), np.linspace(y0, y1, n))
p = np.column_stack([xs.ravel(), ys.ravel()])
covered = np.zeros(len(p), bool)
for x, y, r in zip(g["x"], g["y"], g["r"]):
    near = (np.abs(p[:, 0] - x) < r) & (np.abs(p[:, 1] - y) < r)
    covered[near] |= (p[near, 0] - x) ** 2 + (p[near, 1] - y) ** 2 < r * r
print(f"{d}: solid fraction {covered.mean():.4f} in [{x0}, {x1}] x [{y0}, {y1}] ({n} x {n} points)")
