#!/usr/bin/python3
"""The demo: grains packed into the cavity of an elastic body, the body compressed biaxially, and
the figures a researcher looks at first. Three scenes of this directory, run in turn:

  pack.yaml      `gembem pack`: 300 grains grown in the circular cavity of a 10 x 10 cm elastic
                 square (held rigid while packing) until their mean stress is 20 kgf/cm
  settle.yaml    the host elastic: grains and cavity relax together (the start of the figures)
  compress.yaml  a confining pressure of 100 kgf/cm^2 on the sides, then the top pushed down by
                 0.3 cm (3 % of the height) in 30 steps, the bottom fixed (the end)

then the figures into OUT/figures, each printed with a line on what it shows.

  PYTHONPATH=python /usr/bin/python3 examples/demo/demo.py [OUT] [--grains N] [--steps M]
      OUT      default runs/demo (OUT/packed, OUT/settled, OUT/compressed, OUT/figures)
      --grains the number of grains (the radii scale to the same packing stress)
      --steps  the top's steps (the same 0.3 cm of travel)
tools/demo.sh runs it as it is; ctest `demo_pipeline` with 80 grains and 6 steps.
"""
import argparse
import os
import sys
import time

import numpy as np
from matplotlib.figure import Figure

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
import gembem  # noqa: E402
import gembem.figures as fig  # noqa: E402
from gembem.runner import execute  # noqa: E402

TRAVEL = 0.3  # cm: the top's travel in compress.yaml


def scenes(out, grains=None, steps=None):
    """The three scenes, varied when asked, written into OUT (their file names absolute)."""
    pack = gembem.Scene.load(os.path.join(HERE, "pack.yaml"))
    if grains:
        pack = pack.with_value("pack.count", grains)
    settle = gembem.Scene.load(os.path.join(HERE, "settle.yaml"))
    settle.initial_state = os.path.abspath(os.path.join(out, "packed", "state.yaml"))
    compress = gembem.Scene.load(os.path.join(HERE, "compress.yaml"))
    if steps:
        compress = compress.with_value("loading.1.host_load.steps", steps)
        compress = compress.with_value("loading.1.host_load.increments.top", [0, -TRAVEL / steps])
    return pack, settle, compress


def run_all(out, grains=None, steps=None, quiet=False):
    os.makedirs(out, exist_ok=True)
    pack, settle, compress = scenes(out, grains, steps)
    t0 = time.time()
    execute(["pack", pack.write(os.path.join(out, "packed.yaml")), "-o", os.path.join(out, "packed"), "--overwrite"],
            quiet=quiet)
    settled = gembem.run(settle, os.path.join(out, "settled"), overwrite=True, quiet=quiet, progress=None)
    compress.initial_state = settled
    compressed = gembem.run(compress, os.path.join(out, "compressed"), overwrite=True, quiet=quiet, progress=None)
    return settled, compressed, time.time() - t0


def loading_steps(run):
    """The steps of the top's loading: the compress scene's second stage."""
    s = run.steps
    return s["step"][s["stage"] == 2]


def _panels(figsize, rows, cols):
    """A figure of rows x cols panels, laid out to fit; returns it and its axes."""
    f = Figure(figsize=figsize, layout="constrained")
    return f, f.subplots(rows, cols)


def _save(f, out, name, dpi):
    """Writes the figure to OUT/name; returns that path."""
    path = os.path.join(out, name)
    f.savefig(path, dpi=dpi)
    return path


def draw(settled, compressed, out):
    """The figures; yields (path, what it shows)."""
    os.makedirs(out, exist_ok=True)
    top = loading_steps(compressed)
    first, last = int(top[0]), int(top[-1])
    hs = compressed.host_steps.select(compressed.host_steps["group"] == "top")
    travel = -hs["uy"][-1]
    height = 10.0

    # 1. the host's stress and the force chains, start and end
    f, (a, b) = _panels((12, 5.6), 1, 2)
    u_start = np.abs(settled.host_particles["ux"]).max()
    fig.host_stress(settled, ax=a, title="start: the packed grains press on the elastic body\n"
                    f"(largest cavity displacement {u_start:.2g} cm)")
    fig.host_stress(compressed, ax=b, title=f"end: the body compressed by {100 * travel / height:.1f} %\n"
                    f"(top down {travel:.2f} cm; sides at 100 kgf/cm^2)")
    f.suptitle("Grains in the cavity of an elastic body: the host's in-plane von Mises stress (own scale per panel) "
               "and the force chains (line width proportional to the normal force)", fontsize=10)
    path = _save(f, out, "start_end.png", 110)
    yield path, ("the host's stress around the cavity and the grains' force chains, at the start (packed grains "
                 "pressing on the body) and at the end of the compression")

    # 2. load-displacement, and the stresses in the granular zone
    f, (a, b) = _panels((12, 4.8), 1, 2)
    fig.load_displacement(compressed, "top", "y", ax=a)
    a.set_xlabel("top displacement, downwards [cm]")
    a.set_ylabel("force on the top, downwards [kgf per cm of thickness]")
    a.set_title("the body's load-displacement curve\n(the first points at 0: the confining pressure)", fontsize=10)
    steps = compressed.steps["step"]
    u = -np.array([hs["uy"][hs["step"] == k][0] for k in steps])
    zone = np.array([zone_stress(compressed, int(k)) for k in steps])
    b.plot(u, zone[:, 1], marker="o", ms=2.5, label="grains: vertical stress syy")
    b.plot(u, zone[:, 0], marker="o", ms=2.5, label="grains: horizontal stress sxx")
    b.plot(u, -np.array([hs["fy"][hs["step"] == k][0] for k in steps]) / height, ls="--", color="0.4",
           label="the body's top: force / width")
    b.axhline(100, ls=":", color="0.4", label="the body's sides: confining pressure")
    b.set_xlabel("top displacement, downwards [cm]")
    b.set_ylabel("stress, compression + [kgf/cm^2]")
    b.set_title("stresses in the granular zone (Love's formula over the cavity's area)\n"
                "against the body's nominal stresses", fontsize=10)
    b.grid(alpha=0.3)
    b.legend(fontsize=8)
    path = _save(f, out, "load_displacement.png", 110)
    yield path, ("the body's load-displacement curve (force on the top against its displacement), and the "
                 "granular zone's mean stresses against the body's")

    # 3. hoop stress along the cavity wall, with the grains and empty
    f, (a, b) = _panels((12, 4.6), 1, 2)
    fig.cavity_wall(compressed, [0], ax=a, labels=["start"])
    fig.cavity_wall(compressed, [last], ax=b, labels=["end"])
    a.set_title("start: the grains alone load the cavity", fontsize=10)
    b.set_title(f"end: top down {travel:.2f} cm", fontsize=10)
    f.suptitle("The host's hoop stress along the cavity wall, with the grains (solid) and for an empty cavity under the "
               "same loads (dashed)", fontsize=10)
    path = _save(f, out, "cavity_wall.png", 110)
    yield path, ("the host's hoop stress along the cavity wall at the start and the end, with the grains against "
                 "an empty cavity")

    # 4. strain maps and the localisation index
    f, axes = _panels((11, 9.5), 2, 2)
    fig.strain_map(compressed, first, ax=axes[0, 0],
                   title=f"start: shear strain of the first step of the top (step {first})\n"
                         f"localisation index {_index(compressed, first):.2f} (0.1: uniform)")
    fig.strain_map(compressed, last, ax=axes[0, 1],
                   title=f"end: shear strain of the last step (step {last})\n"
                         f"localisation index {_index(compressed, last):.2f}")
    acc = fig.accumulated_strain(compressed, first, last)
    fig.strain_map(compressed, last, since=first, ax=axes[1, 0],
                   title=f"the whole compression: shear strain of steps {first}-{last}\n"
                         f"localisation index {acc['index']:.2f}")
    fig.localisation_index(compressed, ax=axes[1, 1], stages=[2])
    axes[1, 1].set_xlabel("top displacement, downwards [cm]")
    axes[1, 1].set_title("localisation index of each step's strain increment", fontsize=10)
    f.suptitle("The granular zone's strain (on the triangles of the grain centres; grains outlined, "
               "the cavity's boundary in grey) and its localisation index", fontsize=10)
    path = _save(f, out, "strain_maps.png", 100)
    yield path, ("the granular zone's shear strain in the first and last steps of the compression and over "
                 "all of it, with the localisation index of each step")


def zone_stress(run, step):
    """The granular zone's mean stress (sxx, syy, sxy; compression positive) at a step, by Love's
    formula: the sum over contacts of the force on j times the vector from grain i's centre to j's
    (to the contact point on a boundary particle), over the cavity's area at rest (the polygon of
    its elements' midpoints, fields/host_wall)."""
    c = run.contacts(step)
    t = np.stack([-c["ny"], c["nx"]], 1)
    n = np.stack([c["nx"], c["ny"]], 1)
    force = c["pn"][:, None] * n + c["pt"][:, None] * t
    branch = np.stack([c["xj"] - c["xi"], c["yj"] - c["yi"]], 1)
    w = run.field("host_wall", step)
    area = 0.5 * abs(np.sum(w["x"] * np.roll(w["y"], -1) - np.roll(w["x"], -1) * w["y"]))
    s = force.T @ branch / area
    return s[0, 0], s[1, 1], 0.5 * (s[0, 1] + s[1, 0])


def _index(run, step):
    loc = run.localisation
    return float(loc["localisation_index"][loc["step"] == step][0])


def summary(settled, compressed):
    """A few numbers: does the coupling show?"""
    p = settled.host_particles
    hs = compressed.host_steps
    top = hs.select(hs["group"] == "top")
    pk = compressed.host_particles
    gap = np.hypot(pk["host_fx"] - pk["grain_fx"], pk["host_fy"] - pk["grain_fy"]).max()
    return [f"packed and settled: {len(settled.state.grains['x'])} grains, largest cavity displacement "
            f"{np.hypot(p['ux'], p['uy']).max():.3g} cm from the grains' pressure alone",
            f"compressed: top down {-top['uy'][-1]:.3f} cm, force on the top {-top['fy'][-1]:.4g} kgf/cm, "
            f"{compressed.steps.nrows - 1} steps; the host's force on each cavity element equals the grains' "
            f"to {gap:.2g} kgf (accuracy {compressed.scene['solver']['accuracy']})"]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out", nargs="?", default=os.path.join(HERE, "..", "..", "runs", "demo"))
    ap.add_argument("--grains", type=int)
    ap.add_argument("--steps", type=int)
    ap.add_argument("--quiet", action="store_true", help="no line from gembem")
    ap.add_argument("--figures-only", action="store_true", help="draw the figures of OUT's runs again")
    a = ap.parse_args(argv)
    out = os.path.normpath(a.out)
    if a.figures_only:
        settled, compressed = gembem.Run(os.path.join(out, "settled")), gembem.Run(os.path.join(out, "compressed"))
    else:
        settled, compressed, seconds = run_all(out, a.grains, a.steps, a.quiet)
        print(f"pack + settle + compress: {seconds:.1f} s")
    for line in summary(settled, compressed):
        print(line)
    t0 = time.time()
    made = list(draw(settled, compressed, os.path.join(out, "figures")))
    print(f"figures ({time.time() - t0:.1f} s):")
    for path, what in made:
        print(f"  {os.path.relpath(path)}: {what}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
