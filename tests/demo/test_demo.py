#!/usr/bin/python3
"""The demo's pipeline, reduced (examples/demo/demo.py with 80 grains and 6 steps of the top):
pack, settle, compress and the figures, then checks that can fail, each without gembem's own
summary of it:

  - the packed grains press on the elastic body: after the settle step the cavity's largest
    displacement is far above round-off (> 1e-6 of the body's 10 cm; the flagship demo's old
    packing touched nothing: 1e-16 cm);
  - on every cavity element, the host's force K u + f0 (host_particles.csv) equals the sum of the
    grains' contact forces on its boundary particle, summed here from contacts/ (pn n + pt t), to
    the solver's accuracy, at the end of both runs;
  - the body's boundary forces balance (every group, the cavity included) to 2 % of the largest
    (constant elements: docs/hybrid.md);
  - the load-displacement curve rises: the top's force grows at every step of the top's loading,
    and so does the granular zone's vertical stress (Love's formula), which stays below the body's
    nominal stress (the grains are softer than the host: kn/G = 1 cm);
  - every load step converged without a cut-back, and the localisation index of each loading step
    lies in [0.1, 1];
  - the four figures exist as PNG files of some size;
  - `python3 -m gembem figures` draws every figure each directory allows: on the compression (2 +
    6 steps, every step's contacts and measures kept) the force chains, the last step's rose and
    strain map, the localisation index, the cavity wall, the host's stress and the top's
    load-displacement; on the packing its force chains, size and force distributions;
  - no run warns (run_info.yaml's warnings: empty), the reduced pipeline's runs and the full
    demo's settling of 300 grains, whose mean contact force (4.5 kgf) is the demo's smallest
    against the accuracy.
"""
import os
import shutil
import sys
import tempfile

import numpy as np

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(ROOT, "examples", "demo"))
import demo  # noqa: E402

fails = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        fails.append(what)


def particle_balance(run, step):
    """Largest |host force - grains' force| over the cavity elements at `step` (the run's last)."""
    c = run.contacts(step)
    hp = run.host_particles
    on = np.zeros((hp.nrows, 2))
    for j, pn, pt, nx, ny in zip(c["j"], c["pn"], c["pt"], c["nx"], c["ny"]):
        j = str(j)
        if j.startswith("p"):
            on[int(j[1:])] += pn * np.array([nx, ny]) + pt * np.array([-ny, nx])
    return np.hypot(hp["host_fx"] - on[:, 0], hp["host_fy"] - on[:, 1]).max(), np.abs(on).max()


def warnings(run):
    return run.run_info.get("warnings") or []


def full_settle(out):
    """The demo's own pack (300 grains) and settle, as tools/demo.sh runs them."""
    pack, settle, _ = demo.scenes(out)
    demo.execute(["pack", pack.write(os.path.join(out, "packed.yaml")), "-o", os.path.join(out, "packed")],
                 quiet=True)
    return demo.gembem.run(settle, os.path.join(out, "settled"), quiet=True, progress=None)


def main():
    out = tempfile.mkdtemp(prefix="gembem_demo_")
    try:
        settled = full_settle(os.path.join(out, "full"))
        s = settled.steps
        check(not warnings(settled), f"the demo's settling of {settled.state.grains.nrows} grains warns of nothing "
              f"(accuracy {s['accuracy'][-1]:g}, mean normal contact force {s['mean_normal_force'][-1]:.3g}): "
              f"{warnings(settled)}")
        settled, compressed, seconds = demo.run_all(out, grains=80, steps=6, quiet=True)
        made = list(demo.draw(settled, compressed, os.path.join(out, "figures")))
        print(f"pipeline {seconds:.1f} s; {', '.join(os.path.basename(p) for p, _ in made)}")
        accuracy = compressed.scene["solver"]["accuracy"]
        check(not warnings(settled), f"settled: no warning: {warnings(settled)}")
        # the compression (the top down by 3 % of the body) strains the cavity past the linear host's
        # range, and the host follows its boundary: no warning, and a host rebased after every step
        check(not warnings(compressed), f"compressed: no warning: {warnings(compressed)}")
        check(compressed.scene["host"].get("updated_lagrangian") == {"every": 1},
              f"compressed: the host follows its boundary: {compressed.scene['host'].get('updated_lagrangian')}")

        p = settled.host_particles
        u = np.hypot(p["ux"], p["uy"]).max()
        check(u > 1e-5, f"settled: the cavity's largest displacement {u:.3g} cm > 1e-5 cm (1e-6 of the body)")

        for run in (settled, compressed):
            last = int(run.steps["step"][-1])
            gap, largest = particle_balance(run, last)
            check(largest > 10 * accuracy and gap <= accuracy,
                  f"{os.path.basename(run.path)}: host force K u + f0 = the grains' contact forces on each cavity "
                  f"element to {gap:.3g} (accuracy {accuracy}; largest force {largest:.4g})")

        hs = compressed.host_steps
        last = int(hs["step"][-1])
        end = hs.select(hs["step"] == last)
        total = np.hypot(np.sum(end["fx"]), np.sum(end["fy"]))
        biggest = np.hypot(end["fx"], end["fy"]).max()
        check(total <= 0.02 * biggest, f"the body's boundary forces balance: |sum| {total:.4g} <= 2 % of {biggest:.4g}")

        s = compressed.steps
        loading = s["step"][s["stage"] == 2]
        top = hs.select(hs["group"] == "top")
        fy = -np.array([top["fy"][top["step"] == k][0] for k in loading])
        check(len(loading) == 6 and np.all(np.diff(fy) > 0),
              f"the top's force rises at every loading step: {np.array2string(fy, precision=0)}")
        syy = np.array([demo.zone_stress(compressed, int(k))[1] for k in loading])
        check(np.all(np.diff(syy) > 0) and np.all(syy < fy / 10),
              f"the grains' vertical stress rises and stays below the body's nominal one: "
              f"{np.array2string(syy, precision=0)}")
        check(np.all(s["substeps"][1:] == 1) and np.all(settled.steps["substeps"][1:] == 1),
              "every load step converged without a cut-back (substeps 1)")
        loc = compressed.localisation
        index = np.array([loc["localisation_index"][loc["step"] == k][0] for k in loading])
        check(np.all((index >= 0.1) & (index <= 1)), f"localisation index in [0.1, 1]: {np.round(index, 3)}")

        from gembem.__main__ import main as gembem_main
        expected = {"compressed": {"force_chains.png", "rose_000008.png", "strain_map_000008.png",
                                   "localisation_index.png", "cavity_wall.png", "host_stress.png",
                                   "load_displacement_top.png"},
                    "packed": {"force_chains.png", "size_distribution.png", "force_distribution.png"}}
        for name, files in expected.items():
            into = os.path.join(out, "figures_" + name)
            code = gembem_main(["figures", os.path.join(out, name), into])
            drawn = set(os.listdir(into)) if os.path.isdir(into) else set()
            check(code == 0 and drawn == files, f"python3 -m gembem figures {name}: exit {code}, drew {sorted(drawn)}")
            made += [(os.path.join(into, f), "") for f in sorted(drawn)]

        for path, _ in made:
            with open(path, "rb") as f:
                head = f.read(8)
            check(head == b"\x89PNG\r\n\x1a\n" and os.path.getsize(path) > 20000,
                  f"{os.path.basename(path)}: a PNG of {os.path.getsize(path)} bytes")
    finally:
        shutil.rmtree(out, ignore_errors=True)
    print(f"{len(fails)} failures")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
