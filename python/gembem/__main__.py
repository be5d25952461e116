"""The standard figures of a run directory, from the command line.

    PYTHONPATH=python /usr/bin/python3 -m gembem figures RUN_DIR [OUT_DIR]

Draws what the run has (force chains of the final state, the stress ratio against the shear
strain (box scenes), the convergence of its slowest load step, the last contact rose and strain map, the host's
stress field and load-displacement curve) into OUT_DIR (default RUN_DIR/figures) and prints each
file with a line on what it shows.
"""
import argparse
import os
import sys

import numpy as np

from . import figures
from .rundir import Run


def standard_figures(run, out):
    """Draws every standard figure the run's files allow; yields (path, what it shows)."""
    os.makedirs(out, exist_ok=True)
    has = lambda name: os.path.exists(os.path.join(run.path, name))  # noqa: E731
    s = run.steps
    path = os.path.join(out, "force_chains.png")
    figures.force_chains(run, path=path)
    yield path, "grains of the final state, line width proportional to each contact's normal force"
    if not has("host_steps.csv"):   # a hybrid run has no box: its stresses and strains are 0
        path = os.path.join(out, "stress_strain.png")
        figures.stress_strain(run, path=path)
        yield path, "stress ratio (s1 - s2)/(s1 + s2) against e1 - e2, every load step"
    if has("history.csv") and run.history.nrows:
        step = int(s["step"][np.argmax(s["iterations"])])
        if np.any(run.history["step"] == step):
            path = os.path.join(out, f"convergence_{step:06d}.png")
            figures.convergence(run, step, path=path)
            yield path, f"largest fixing force per iteration of load step {step}, the one with most iterations"
    roses = run.steps_of("contacts", "rose")
    if roses:
        path = os.path.join(out, f"rose_{roses[-1]:06d}.png")
        figures.rose(run, roses[-1], path=path)
        yield path, f"contact directions at step {roses[-1]}"
    maps = run.steps_of("fields", "triangles", "vtu")
    if maps:
        path = os.path.join(out, f"strain_map_{maps[-1]:06d}.png")
        figures.strain_map(run, maps[-1], path=path)
        yield path, f"shear strain increment of step {maps[-1]} on the grain centres' triangles"
    if has("host_field.vtu"):
        path = os.path.join(out, "host_stress.png")
        figures.host_stress(run, path=path)
        yield path, "the host's in-plane von Mises stress at the end, under the grains' force chains"
        pick = figures.loaded_group(run)
        if pick is None:
            return
        group, axis = pick
        path = os.path.join(out, f"load_displacement_{group}.png")
        figures.load_displacement(run, group, axis, path=path)
        yield path, f"force on the host's '{group}' against its displacement along {axis} (the loaded group)"

def main(argv=None):
    ap = argparse.ArgumentParser(prog="python3 -m gembem", description=__doc__.split("\n")[0])
    sub = ap.add_subparsers(dest="command", required=True)
    f = sub.add_parser("figures", help="the standard figures of a run directory")
    f.add_argument("run_dir")
    f.add_argument("out_dir", nargs="?")
    a = ap.parse_args(argv)
    try:
        run = Run(a.run_dir)
        for path, what in standard_figures(run, a.out_dir or os.path.join(a.run_dir, "figures")):
            print(f"{path}: {what}")
    except (OSError, ValueError, KeyError) as e:
        print(f"gembem figures: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
