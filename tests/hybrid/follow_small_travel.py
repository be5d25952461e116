#!/usr/bin/python3
"""A host that follows its boundary (host.updated_lagrangian: every step) against the host at rest,
on the 27-grain packing of tests/hybrid/load_grains.yaml (relax, a confining pressure, the top
pushed) with its loads scaled by 0.1, 1 and 10: the two differ by the change of the body's
geometry, which is of the order of the strain, so the cavity displacements (host_particles.csv)
must agree to a fraction of the cavity's strain (u / R: the largest displacement over the mean
radius of the cavity's midpoints) and the difference must fall with the travel. Measured: 0.04-0.14
of u / R (docs/hybrid.md "A host that follows its boundary").
  follow_small_travel.py GEMBEM OUT"""
import os
import subprocess
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FRACTION = 0.5  # of u / R: the geometric effect is first order in the strain, with a factor below 1 here


def edit(src, dst, *args):
    env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "python"))
    subprocess.run(["/usr/bin/python3", "-m", "gembem", "scene", src, "-o", dst, *args], check=True, env=env)


def cavity(run):
    a = np.genfromtxt(os.path.join(run, "host_particles.csv"), delimiter=",", names=True)
    return np.stack([a["ux"], a["uy"]], 1), np.hypot(a["x"], a["y"]).mean()


def main():
    gembem, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    fails, diffs = 0, []
    for s in (0.1, 1.0, 10.0):
        runs = []
        for follow in (False, True):
            name = os.path.join(out, "s%g_%s" % (s, "followed" if follow else "rest"))
            args = ["--set", "loading.1.host_load.increments={left: %g, right: %g}" % (10 * s, 10 * s),
                    "--set", "loading.2.host_load.increments={top: [%g, %g]}" % (0.0005 * s, -0.001 * s)]
            if follow:
                args += ["--add", "host.updated_lagrangian={every: 1}"]
            edit(os.path.join(ROOT, "tests", "hybrid", "load_grains.yaml"), name + ".yaml", *args)
            subprocess.run([gembem, "run", name + ".yaml", "-o", name, "--overwrite", "--quiet"], check=True)
            runs.append(cavity(name))
        (u_rest, radius), (u_fol, _) = runs
        scale = np.abs(u_rest).max()
        d, strain = np.abs(u_fol - u_rest).max() / scale, scale / radius
        diffs.append(d)
        ok = 0 < d <= FRACTION * strain
        fails += not ok
        print("%s loads x %g: cavity displacement up to %.3g (u / R %.3g); followed - at rest %.3g of it (%.2f u / R)"
              % ("ok  " if ok else "FAIL", s, scale, strain, d, d / strain))
    ok = diffs[0] < diffs[1] < diffs[2]
    fails += not ok
    print("%s the difference grows with the travel: %s" % ("ok  " if ok else "FAIL", ", ".join("%.3g" % d for d in diffs)))
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
