#!/usr/bin/python3
"""A run's work per load step, for tools/bench_hard_hybrid.sh (docs/run-directory.md's files).

    bench_hard_hybrid_table.py RUN_DIR [--exit CODE]

From steps.csv: per step its iterations, smoother sweeps, factorisations, trials, cut-back
substeps, seconds, largest fixing force over the step's accuracy, and the step's sweeps and
iterations over the median step's (steps 1 on; step 0 is the initial state). A step that was
running when the run stopped (a timeout) has no row there: its iterations and fixing forces come
from history.csv (with `solver: {history: true}`). Then whether the run completed (run_info.yaml's
status, the exit code: 124 is timeout's), and the costliest step's convergence from history.csv:
the largest fixing force at a few points of the step, its lowest and where, how often a new
lowest was reached, and the longest stretch of iterations without one (a plateau or a cycle
shows as a long stretch; a slow creep as many small new lows).
"""
import csv
import math
import os
import statistics
import sys


def read_rows(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def run_status(run_dir):
    """run_info.yaml's top-level `status:` and `message:` (plain lines; no YAML library needed)."""
    status, message = "none", ""
    path = os.path.join(run_dir, "run_info.yaml")
    if os.path.exists(path):
        with open(path) as f:
            for line in f:
                if line.startswith("status:"):
                    status = line.split(":", 1)[1].strip().strip('"')
                elif line.startswith("message:"):
                    message = line.split(":", 1)[1].strip().strip('"')
    return status, message


def ratio(value, median):
    """value over the median step's; inf over a median of 0 (a run whose median step did no such work)."""
    return value / median if median > 0 else math.inf if value > 0 else 1.0


def history_shape(rows):
    """The largest fixing force's course over one step's iterations (all attempts in order)."""
    forces = [float(r["max_fixing_force"]) for r in rows]
    n = len(forces)
    lows, best, best_at, longest, since = 0, math.inf, 0, 0, 0
    for i, f in enumerate(forces):
        if f < best:
            best, best_at, lows, since = f, i, lows + 1, 0
        else:
            since += 1
            longest = max(longest, since)
    points = sorted({0, n // 10, n // 4, n // 2, 3 * n // 4, 9 * n // 10, n - 1})
    progress = sum(1 for r in rows if r.get("smoother", "0") == "1")
    smoother = sum(1 for r in rows if r.get("smoother", "0") == "0" and float(r["length"]) == 0.0)
    attempts = len({r["attempt"] for r in rows})
    lines = [f"  history rows {n} (attempts {attempts}; iterations where the smoother took over, length 0:"
             f" {smoother}; the smoother's progress rows: {progress})",
             "  largest fixing force at row: " + ", ".join(f"{i + 1}: {forces[i]:.3g}" for i in points),
             f"  lowest {best:.3g} at row {best_at + 1}; new lows {lows}; longest stretch without a new low {longest} rows"]
    tail = forces[n // 2:]
    if tail:
        lines.append(f"  second half: min {min(tail):.3g}, median {statistics.median(tail):.3g}, max {max(tail):.3g}")
    period = cycle_period(forces)
    if period:
        last = forces[-period:]
        lines.append(f"  the last {CYCLE_ROWS} rows repeat with period {period} to {CYCLE_TOL:g} of the force:"
                     f" a cycle through {', '.join(f'{f:.4g}' for f in last)}")
    return lines


CYCLE_ROWS, CYCLE_TOL = 20, 1e-3


def cycle_period(forces):
    """The smallest p in 1..8 with |f[i] - f[i-p]| <= CYCLE_TOL f[i] over the last CYCLE_ROWS rows
    (p = 1: a plateau), or 0."""
    if len(forces) < CYCLE_ROWS + 8:
        return 0
    for p in range(1, 9):
        if all(abs(forces[i] - forces[i - p]) <= CYCLE_TOL * forces[i] for i in range(len(forces) - CYCLE_ROWS, len(forces))):
            return p
    return 0


def checkpoint_work(run_dir):
    """(iterations, trials, factorisations, sweeps) of the step in progress at the last checkpoint
    written within a step (checkpoint.txt's `progress` and `work` lines, src/io/checkpoint.c), or None."""
    path = os.path.join(run_dir, "checkpoint.txt")
    if not os.path.exists(path):
        return None
    iters = None
    with open(path, errors="replace") as f:
        for line in f:
            w = line.split()
            if w and w[0] == "progress" and len(w) == 8:
                iters = int(w[3]) + int(w[6])   # the ended attempts' and the current relaxation's
            elif w and w[0] == "work" and len(w) == 4:
                return (iters, int(w[1]), int(w[2]), int(w[3]))
    return None


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    run_dir = sys.argv[1]
    code = sys.argv[sys.argv.index("--exit") + 1] if "--exit" in sys.argv else "?"
    steps = [r for r in read_rows(os.path.join(run_dir, "steps.csv")) if int(r["step"]) > 0]
    history = read_rows(os.path.join(run_dir, "history.csv"))
    status, message = run_status(run_dir)
    case = os.path.basename(os.path.normpath(run_dir))

    med_sweeps = statistics.median([int(r["sweeps"]) for r in steps]) if steps else 0
    med_iters = statistics.median([int(r["iterations"]) for r in steps]) if steps else 0
    print(f"{case}: status {status}, exit {code}" + (f" ({message})" if message else ""))
    print(f"  median step: {med_iters:g} iterations, {med_sweeps:g} sweeps")
    print(f"{'step':>4} {'stage':>5} {'iters':>7} {'sweeps':>10} {'factor':>6} {'trials':>7} {'sub':>3}"
          f" {'seconds':>9} {'fix/acc':>7} {'sweeps/med':>10} {'iters/med':>9}")
    for r in steps:
        sweeps, iters = int(r["sweeps"]), int(r["iterations"])
        rs, ri = ratio(sweeps, med_sweeps), ratio(iters, med_iters)
        mark = "  <- >10x" if rs > 10 or ri > 10 else ""
        print(f"{r['step']:>4} {r['stage']:>5} {iters:>7} {sweeps:>10} {r['factorisations']:>6} {r['trials']:>7}"
              f" {r['substeps']:>3} {float(r['seconds']):>9.2f}"
              f" {float(r['max_fixing_force']) / float(r['accuracy']):>7.3f} {rs:>10.1f} {ri:>9.1f}{mark}")
    done = {r["step"] for r in steps}
    unfinished = [r for r in history if r["step"] not in done]
    if unfinished:
        step = unfinished[-1]["step"]
        rows = [r for r in unfinished if r["step"] == step]
        print(f"{step:>4}     - {len(rows):>7}          ? (unfinished: history.csv's rows; last largest"
              f" fixing force {float(rows[-1]['max_fixing_force']):.3g})")
        work = checkpoint_work(run_dir)
        if work:
            print(f"      at its last checkpoint: {work[0]} iterations, {work[1]} trials, {work[2]} factorisations,"
                  f" {work[3]} sweeps" + (f" ({ratio(work[3], med_sweeps):.1f} x the median step's)" if steps else ""))

    # The costliest step: most sweeps among the finished ones, or the unfinished one.
    if unfinished:
        worst = unfinished[-1]["step"]
    elif steps:
        worst = max(steps, key=lambda r: (int(r["sweeps"]), int(r["iterations"])))["step"]
    else:
        return
    rows = [r for r in history if r["step"] == worst]
    print(f"  costliest step {worst}:")
    if rows:
        for line in history_shape(rows):
            print(line)
    else:
        print("  (no history.csv rows: run with solver: {history: true})")


if __name__ == "__main__":
    main()
