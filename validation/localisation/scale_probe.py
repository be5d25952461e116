#!/usr/bin/python3
"""One case of the localisation statistics (study.py's k0.01_p100_nr, seed 1) at another size: N
grains in the same cavity, its boundary in M elements (the statistics: 1000 grains, 128 elements;
M grows with sqrt(N) to keep the boundary particles' size to the grains'), packed by gembem pack,
then the case's scene (confinement, then 24 top steps of 0.01 cm) run by gembem run. How long a run
at a size where a band could form takes, and how far its zone strains.

Usage: validation/localisation/scale_probe.py N M DIR [BUILD_DIR] [--steps S] [--follow K]
       (e.g. 10000 384 runs/probe)
--steps S: S top steps of 0.01 cm instead of the case's 24; --follow K: the host follows its
deformed boundary, rebased after every K steps (host.updated_lagrangian), for travel past the
linear host's range.
Writes DIR/pack.yaml, DIR/pack/, DIR/grains.csv, DIR/scene.yaml and the run directory DIR/run."""
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "python"))
sys.path.insert(0, HERE)
import study as loc  # noqa: E402
from gembem import read_state, write_grains_csv  # noqa: E402


def option(args, name):
    """The value of --name V in args (removed from it), or None."""
    if name not in args:
        return None
    k = args.index(name)
    if k + 1 >= len(args):
        raise SystemExit(__doc__)
    value = args[k + 1]
    del args[k:k + 2]
    return int(value)


def main():
    args = sys.argv[1:]
    steps, follow = option(args, "--steps"), option(args, "--follow")
    if len(args) not in (3, 4):
        raise SystemExit(__doc__)
    loc.STAT_N, loc.STAT_CAVITY, d = int(args[0]), int(args[1]), args[2]
    gembem = os.path.join(args[3] if len(args) == 4 else os.path.join(ROOT, "build"), "gembem")

    name, mesh = "k0.01_p100_nr/s01", os.path.join(ROOT, "meshes", "square_cavity_sides.geo")
    os.makedirs(d, exist_ok=True)
    loc.write_pack_scene(name, os.path.join(d, "pack.yaml"), mesh)
    subprocess.run([gembem, "pack", os.path.join(d, "pack.yaml"), "-o", os.path.join(d, "pack"), "--overwrite",
                    "--quiet"], check=True)
    g = read_state(os.path.join(d, "pack")).grains
    write_grains_csv(os.path.join(d, "grains.csv"), np.column_stack([g["x"], g["y"], g["r"]]))
    case = loc.stat_case(name)
    sc = loc.stat_like_scene(name, case, mesh, loc.STAT_N, loc.STAT_CAVITY,
                             steps if steps is not None else loc.STAT_STEPS[case[1]], follow)
    sc.write(os.path.join(d, "scene.yaml"), comment=loc.scene_comment(name))
    subprocess.run([gembem, "run", os.path.join(d, "scene.yaml"), "-o", os.path.join(d, "run"), "--overwrite"],
                   check=True)


if __name__ == "__main__":
    main()
