#!/usr/bin/python3
"""Runs an extended case of the localisation study over its whole travel, continuing past a load
step that does not converge.

Segment 0 is the case's scene (study.py scene NAME: a gembem.Scene). When a segment stops (gembem exit 3: a load
step did not converge in max_iterations), a bridge segment starts from the last converged state
(`initial_state:`; restarting is exact, docs/hybrid.md "Restarting a hybrid run") and goes over the next
HALVED steps' worth of travel in steps half as long; a bridge that stops without a step done is
tried again one level further (BRIDGES: steps / 4, then also the accuracy a 4 and 16 times
looser); a bridge that stops after some steps is followed by a level-1 bridge from there. After a
bridge that completes, a segment goes on at the case's step and accuracy. Nothing of the solver
is changed: only the step, and within bridges the accuracy, where a step stalled (segments.csv
says where). The case gives up after MAX_SEGMENTS segments, when the last level fails, or when
gembem refuses the restart (exit 2: it checks the grains against the cavity at rest, and once the
cavity has moved by about a grain's radius a grain at the wall lies outside it).

An attempt that stops short of the whole travel is followed by one from the start with all the
top's steps half as long (ATTEMPTS; the path differs, and so do its stalls); the one that got
further is kept. Writes NAME/attemptK/seg00, seg01, ... (gembem runs), scene_segNN.yaml,
segments.csv (one row per segment: segment, first global step, steps, exit status, travel at its
end, seconds, the largest fixing force of the step that stopped it, the step divisor and accuracy
factor of a bridge), status.txt; and NAME/attempt.txt, the attempt kept. figures.py stitches its
segments.

Usage: run_continued.py NAME OUTDIR MESH GEMBEM
"""
import csv
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
import gembem  # noqa: E402
import study  # noqa: E402

HALVED = 5         # steps of the case's size gone over by a bridge after a stall
MAX_SEGMENTS = 40


def top_travel(run, shear):
    """The top's travel (|uy| for biaxial, |ux| for shear) at the last row of host_steps.csv."""
    h = gembem.read_csv(os.path.join(run, "host_steps.csv"))
    top = h.select(h["group"] == "top")
    return int(top["step"][-1]), abs(float(top["ux" if shear else "uy"][-1]))


def continued_scene(base, state, parts, shear, accuracy):
    """The case's scene (gembem.Scene) started from `state` with the loading `parts`
    [(steps, du), ...] and the accuracy (6 significant digits, as the case's)."""
    inc = lambda du: [study.g6(du), 0] if shear else [0, study.g6(-du)]
    s = base.with_value("grains", None).with_value("initial_state", state)
    s = s.with_value("loading", [{"host_load": {"steps": steps, "increments": {"top": inc(du)}}} for steps, du in parts])
    return s.with_value("solver.accuracy", study.g6(accuracy))


BRIDGES = [(2, 1), (4, 4), (4, 16)]  # a bridge's (step divisor, accuracy factor), level by level


def attempt(name, out, mesh, gembem, refine):
    """One attempt in `out`: the case's scene with its steps `refine` times smaller, continued past
    its stalls; returns the travel reached and whether it is the whole."""
    c = study.ext(name)
    shear = c["load"] == "shear"
    du, total = c["du"] / refine, c["du"] * c["steps"]
    base = study.scene(name, mesh, refine)
    a0 = base.solver["accuracy"]
    rows, first, seg, level, t_all = [], 0, 0, 0, time.time()
    scene = base
    while True:
        sp = scene.write(os.path.join(out, f"scene_seg{seg:02d}.yaml"), comment=study.scene_comment(name))
        run = os.path.join(out, f"seg{seg:02d}")
        t0 = time.time()
        with open(os.path.join(out, f"gembem_seg{seg:02d}.log"), "w") as log:
            rc = subprocess.call([gembem, "run", sp, "-o", run, "--overwrite", "--quiet"], stdout=log,
                                 stderr=subprocess.STDOUT)
        secs = time.time() - t0
        msg = open(os.path.join(out, f"gembem_seg{seg:02d}.log")).read().strip().splitlines()
        msg = msg[-1] if msg else ""
        div, fac = (1, 1) if level == 0 else BRIDGES[level - 1]
        if not os.path.exists(os.path.join(run, "host_steps.csv")):
            rows.append([seg, first, 0, rc, "", f"{secs:.1f}", msg, div, fac])
            break
        last, travel = top_travel(run, shear)
        m = re.search(r"largest fixing force ([0-9.eE+-]+)", msg)
        rows.append([seg, first, last, rc, f"{travel:.6f}", f"{secs:.1f}", m.group(1) if m else "", div, fac])
        print(f"{name} segment {seg} (steps / {div}, accuracy x {fac}): exit {rc}, {last} steps, "
              f"travel {travel:.4f} cm, {secs:.0f} s" + (f": {msg}" if rc else ""), flush=True)
        first += last
        left = total - travel
        if rc not in (0, 3) or left < 1e-9 or seg + 1 >= MAX_SEGMENTS:
            break
        if rc == 0:  # a bridge done: on at the case's step and accuracy
            level, parts, acc = 0, [(int(round(left / du)), du)], a0
        else:
            # Stopped: a bridge from its last state over the next HALVED steps' travel, in smaller
            # steps; one level further (smaller steps, then a looser accuracy) if this one was a
            # bridge that made no progress.
            level = level + 1 if (level > 0 and last == 0) else max(level, 1)
            if level > len(BRIDGES):
                break
            div, fac = BRIDGES[level - 1]
            small = du / div
            parts, acc = [(int(round(min(left, HALVED * du) / small)), small)], a0 * fac
        state = os.path.relpath(os.path.join(run, "state.yaml"), out)
        scene = continued_scene(base, state, parts, shear, acc)
        seg += 1
    with open(os.path.join(out, "segments.csv"), "w") as f:
        w = csv.writer(f)
        w.writerow(["segment", "first_step", "steps", "exit", "travel", "seconds", "stall_fixing_force",
                    "step_divisor", "accuracy_factor"])
        w.writerows(rows)
    travel = max([float(r[4]) for r in rows if r[4] != ""] or [0.0])
    done = abs(travel - total) < 1e-6
    with open(os.path.join(out, "status.txt"), "w") as f:
        f.write(f"{name} {'exit 0' if done else 'stopped'} {time.time() - t_all:.0f} s, {len(rows)} segments, "
                f"travel {travel:.4f} of {total:g} cm, {sum(1 for r in rows if r[3] == 3)} stalls, "
                f"steps / {refine}\n")
    print(open(os.path.join(out, "status.txt")).read().strip(), flush=True)
    return travel, done


ATTEMPTS = [1, 2]  # the step divisors of the attempts from the start, tried until one goes the whole way


def main():
    name, out, mesh, gembem = sys.argv[1:5]
    best = None
    for q, refine in enumerate(ATTEMPTS, 1):
        d = os.path.join(out, f"attempt{q}")
        shutil.rmtree(d, ignore_errors=True)
        os.makedirs(d)
        shutil.copy(os.path.join(out, "grains.csv"), d)
        travel, done = attempt(name, d, mesh, gembem, refine)
        if best is None or travel > best[1] + 1e-9:
            best = (q, travel)
        if done:
            break
    with open(os.path.join(out, "attempt.txt"), "w") as f:
        f.write(f"attempt{best[0]}\n")


if __name__ == "__main__":
    main()
