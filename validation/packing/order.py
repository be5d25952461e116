#!/usr/bin/python3
"""Hexatic bond-orientational order of a packing (state_grains.csv of a gembem pack directory): the
neighbours of a grain are those of the Delaunay triangulation of the centres (scipy), and
psi6 = mean over its neighbours of exp(6 i theta), theta the angle of the bond. Over the grains
whose centres lie in the window [X0, X1] x [Y0, Y1] (away from the walls, whose flat layers and
hull edges are not the bulk's), prints the mean of |psi6| (the local order: 1 in a triangular
crystal, much less in a disordered packing) and |mean psi6| (the global order: 1 in one crystal,
near 0 without long-range order), the measures of Schreck, O'Hern and Shattuck (arXiv:1007.2162) for disc packings.

  order.py PACKDIR X0 X1 Y0 Y1
"""
import os
import sys

import numpy as np
from scipy.spatial import Delaunay

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import gembem  # noqa: E402

d, x0, x1, y0, y1 = sys.argv[1], *map(float, sys.argv[2:6])
g = gembem.read_state(d).grains
p = np.column_stack([g["x"], g["y"]])
tri = Delaunay(p)
edges = np.vstack([tri.simplices[:, [0, 1]], tri.simplices[:, [1, 2]], tri.simplices[:, [2, 0]]])
edges = np.unique(np.sort(edges, axis=1), axis=0)
bond = p[edges[:, 1]] - p[edges[:, 0]]
term = np.exp(6j * np.arctan2(bond[:, 1], bond[:, 0]))  # the same from either end: 6 pi apart
n = len(p)
s, k = np.zeros(n, complex), np.zeros(n)
for end in (0, 1):
    np.add.at(s, edges[:, end], term), np.add.at(k, edges[:, end], 1)
inside = (p[:, 0] >= x0) & (p[:, 0] <= x1) & (p[:, 1] >= y0) & (p[:, 1] <= y1)
psi = s[inside] / k[inside]
print(f"{d}: {inside.sum()} grains in [{x0}, {x1}] x [{y0}, {y1}]: local order mean |psi6| "
      f"{np.abs(psi).mean():.3f}, global order |mean psi6| {abs(psi.mean()):.4f}, {k[inside].mean():.2f} neighbours")
