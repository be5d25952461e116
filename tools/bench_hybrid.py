#!/usr/bin/python3
"""Benchmark of the hybrid solver (not a test): N grains (diameters 1.0 and 0.6 cm, 15 % large,
as in validation C) placed at random, slightly overlapping, in the circular cavity of an elastic
square (4 R x 4 R, outer boundary fixed, G = 95000 kgf/cm^2, nu = 0.1), cavity elements about
0.65 cm long as in validation C, relaxed to equilibrium (a = 1e-3 kgf) with UMFPACK and CHOLMOD.

usage: [SOLVERS="umfpack cholmod"] tools/bench_hybrid.py [BUILD_DIR] [N ...]   (default: build, 27 1000 10000)
prints a Markdown table (build/bench_hybrid does the timing)
"""
import math
import os
import random
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "python"))
import gembem  # noqa: E402

BUILD = os.path.join(ROOT, sys.argv[1] if len(sys.argv) > 1 else "build")
SIZES = [int(a) for a in sys.argv[2:]] or [27, 1000, 10000]
OUT = os.path.join(ROOT, "runs", "bench_hybrid")


def place(n, usable, rng):
    """Random sequential placement with overlaps of at most a fifth of the small radius."""
    radii = sorted(([0.5] * max(1, round(0.15 * n)) + [0.3] * n)[:n], reverse=True)
    cell, grid, out = 1.2, {}, []
    for r in radii:
        for _ in range(200000):
            a, d = rng.uniform(0, 2 * math.pi), (usable - r) * math.sqrt(rng.random())
            x, y = d * math.cos(a), d * math.sin(a)
            cx, cy = int(math.floor(x / cell)), int(math.floor(y / cell))
            ok = True
            for i in range(cx - 1, cx + 2):
                for j in range(cy - 1, cy + 2):
                    for gx, gy, gr in grid.get((i, j), ()):
                        if math.hypot(x - gx, y - gy) <= r + gr - 0.06:
                            ok = False
            if ok:
                grid.setdefault((cx, cy), []).append((x, y, r))
                out.append((x, y, r))
                break
        else:
            raise SystemExit(f"could not place {n} grains")
    return out


def scene(n):
    area = (0.15 * math.pi * 0.25 + 0.85 * math.pi * 0.09) * n
    usable = math.sqrt(area / (0.5 * math.pi))  # about half the cavity's area covered
    R = usable + 0.33
    ncav = max(24, round(2 * math.pi * R / 0.65))
    d = os.path.join(OUT, f"n{n}")
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "host.geo"), "w") as f:
        f.write(f"""// A square 4R x 4R with a circular cavity of radius R = {R:.4f} (bench_hybrid.py)
L = {4 * R:.6f}; R = {R:.6f}; lc = 1.0;
Point(1) = {{-L/2, -L/2, 0, lc}}; Point(2) = {{L/2, -L/2, 0, lc}};
Point(3) = {{L/2, L/2, 0, lc}};   Point(4) = {{-L/2, L/2, 0, lc}};
Line(1) = {{1, 2}}; Line(2) = {{2, 3}}; Line(3) = {{3, 4}}; Line(4) = {{4, 1}};
Point(5) = {{0, 0, 0, lc}};
Point(6) = {{R, 0, 0, lc}}; Point(7) = {{0, R, 0, lc}}; Point(8) = {{-R, 0, 0, lc}}; Point(9) = {{0, -R, 0, lc}};
Circle(5) = {{6, 5, 7}}; Circle(6) = {{7, 5, 8}}; Circle(7) = {{8, 5, 9}}; Circle(8) = {{9, 5, 6}};
Curve Loop(1) = {{1, 2, 3, 4}};
Curve Loop(2) = {{5, 6, 7, 8}};
Plane Surface(1) = {{1, 2}};
Physical Curve("outer") = {{1, 2, 3, 4}};
Physical Curve("cavity") = {{5, 6, 7, 8}};
""")
    grains = [(round(x, 6), round(y, 6), r) for x, y, r in place(n, usable - 0.02, random.Random(n))]
    return gembem.Scene(
        units={"length": "cm", "force": "kgf"},
        materials={"grain_grain": {"kn": 1000, "kt": 700, "friction_deg": 25},
                   "grain_wall": {"kn": 1000, "kt": 700, "friction_deg": 0}},
        host={"mesh": "host.geo", "elements": {"outer": 80, "cavity": ncav},
              "material": {"shear_modulus": 95000, "poisson": 0.1, "plane": "strain"},
              "boundary": {"outer": "fixed"}, "cavity": "cavity"},
        grains=grains, solver={"method": "global", "linear": "umfpack", "accuracy": 0.001, "max_iterations": 5000},
        loading=[{"relax": {"steps": 1}}]).write(os.path.join(d, "scene.yaml"), grains_file="grains.csv",
                                                comment=f"bench_hybrid.py: {n} grains in the cavity of host.geo")


def main():
    print("| solver | grains | cavity elements | host set-up s | iterations | s per iteration | assembly s | "
          "analysis s (count) | factorisation s (count) | solve s | rest s | total s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for n in SIZES:
        path = os.path.join(ROOT, "validation", "cavity_packing", "scene.yaml") if n == 27 else scene(n)
        for lin in os.environ.get("SOLVERS", "umfpack cholmod").split():
            r = subprocess.run([os.path.join(BUILD, "bench_hybrid"), path, lin], capture_output=True, text=True)
            print(r.stdout.strip() or f"| {lin} | {n} | failed: {r.stderr.strip()} |", flush=True)


if __name__ == "__main__":
    main()
