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
xs, ys = np.linspace(x0, x1, n), np.linspace(y0, y1, n)
covered = np.zeros((n, n), bool)  # [row: y, column: x]
hx, hy = (x1 - x0) / (n - 1), (y1 - y0) / (n - 1)
for x, y, r in zip(g["x"], g["y"], g["r"]):
    # only the grid's points in the disc's bounding box (a margin of one point each side)
    i0, i1 = max(0, int((x - r - x0) / hx) - 1), min(n, int((x + r - x0) / hx) + 2)
    j0, j1 = max(0, int((y - r - y0) / hy) - 1), min(n, int((y + r - y0) / hy) + 2)
    if i0 >= i1 or j0 >= j1:
        continue
    px, py = xs[i0:i1], ys[j0:j1]
    covered[j0:j1, i0:i1] |= ((px[None, :] - x) ** 2 + (py[:, None] - y) ** 2 < r * r) & \
        (np.abs(px[None, :] - x) < r) & (np.abs(py[:, None] - y) < r)
print(f"{d}: solid fraction {covered.mean():.4f} in [{x0}, {x1}] x [{y0}, {y1}] ({n} x {n} points)")
