#!/usr/bin/python3
"""Grains packed in the circular cavity of the localisation study, seeded and deterministic.

N discs with radii uniform in [0.75, 1.25] x r0 (size ratio 5:3) are dropped at random points of
the cavity's usable disc (its radius less the boundary particles' bulge: a particle is a half-disc
of diameter the element's length on the midpoint of a chord of the polygon), with radii a third of
their final size; the radii then grow in steps to the target solid fraction phi (grain area over
the usable disc's area) while overlaps are pushed apart (each overlapping pair separated by half
its overlap per sweep, grains kept inside the usable disc). Dense targets keep small overlaps: the
largest and mean overlap (over the smaller radius) are printed; gembem relaxes them at step 0.

Usage: pack_cavity.py --n 250 --phi 0.82 --seed 1 [--radius 2.5 --elements 64] > grains.csv
"""
import argparse
import math
import sys

import numpy as np


def pack(n, phi, seed, radius, elements, sweeps=400):
    rng = np.random.default_rng(seed)
    usable = radius * math.cos(math.pi / elements) - radius * math.sin(math.pi / elements)
    u = rng.uniform(0.75, 1.25, n)
    r_final = u * math.sqrt(phi * usable**2 / np.sum(u**2))
    a = rng.uniform(0, 2 * math.pi, n)
    d = (usable - r_final) * np.sqrt(rng.random(n))
    x, y = d * np.cos(a), d * np.sin(a)
    iu = np.triu_indices(n, 1)
    for s in range(sweeps):
        grow = min(1.0, 1 / 3 + (2 / 3) * s / (0.6 * sweeps))
        r = r_final * grow
        for _ in range(5):
            dx, dy = x[:, None] - x[None, :], y[:, None] - y[None, :]
            dist = np.sqrt(dx**2 + dy**2) + np.eye(n)
            ov = np.clip(r[:, None] + r[None, :] - dist, 0, None)
            np.fill_diagonal(ov, 0)
            push = 0.5 * ov / dist
            x += np.sum(push * dx, axis=1)
            y += np.sum(push * dy, axis=1)
            rc = np.hypot(x, y)
            out = rc > usable - r
            scale = np.where(out, (usable - r) / np.maximum(rc, 1e-300), 1.0)
            x, y = x * scale, y * scale
    r = r_final
    dist = np.hypot(x[:, None] - x[None, :], y[:, None] - y[None, :])
    ov = (r[:, None] + r[None, :] - dist)[iu] / np.minimum(r[:, None], r[None, :])[iu]
    ov = ov[ov > 0]
    return x, y, r, usable, ov


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--n", type=int, default=250)
    p.add_argument("--phi", type=float, default=0.82)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--radius", type=float, default=2.5)
    p.add_argument("--elements", type=int, default=64)
    a = p.parse_args()
    x, y, r, usable, ov = pack(a.n, a.phi, a.seed, a.radius, a.elements)
    print(f"# pack_cavity.py --n {a.n} --phi {a.phi} --seed {a.seed}: usable radius {usable:.5f}, "
          f"solid fraction {np.sum(r**2) / usable**2:.4f}, mean radius {r.mean():.5f}, "
          f"{ov.size} overlapping pairs, largest overlap {ov.max() if ov.size else 0:.4f} r_min, "
          f"mean {ov.mean() if ov.size else 0:.4f}")
    print("x,y,r")
    for xi, yi, ri in zip(x, y, r):
        print(f"{xi:.6f},{yi:.6f},{ri:.6f}")
    print(f"pack_cavity: phi {a.phi}: {ov.size} overlaps, largest {ov.max() if ov.size else 0:.4f} r_min",
          file=sys.stderr)


if __name__ == "__main__":
    main()
