#!/usr/bin/python3
"""The statistics of tools/bench_peer.sh's shear runs (RUNS=shear): the constant-volume biaxial
shear to e1 = 5 % by gembem (load steps) and LAMMPS (walls at constant velocity, several rates and
start-velocity seeds), compared as statistics, not curve against curve (the path is chaotic).

    tools/shear_stats.py RUNS.tsv [--curves OUT.csv] [--strain 0.05] [--every 0.0025]

RUNS.tsv: a header line, then one run a line, tab-separated: n, code (gembem or lammps), label,
status, steps (gembem's load steps or LAMMPS's time steps), seed (LAMMPS's start velocities; empty
for gembem), curve (gembem's steps.csv or LAMMPS's curve.txt: e1, s1, s2 from the start), cpu
(CPU seconds of the loading), wall (s), mb (peak memory), force (gembem's end state's largest
fixing force by tools/check_equilibrium.py).

For every run: q = (s1 - s2) / 2 and p = (s1 + s2) / 2, divided by the run's own start stress p0
(p at e1 = 0), at every --every of e1 up to --strain (linear interpolation between the run's
points: gembem's load steps need not fall on the grid); the path means are the means over those
points (0.25 %, 0.5 %, ... 5 %: the start left out). A run that stopped short has no path mean.
Printed as Markdown: a row per run (gembem's work a load step from steps.csv: Newton iterations,
smoother steps, factorisations, mean / median / max over the load steps, and how many were cut
back into sub-steps), then LAMMPS's own spread
between rates and between repeats, and gembem's path means against LAMMPS's slowest run.
--curves writes every run's q/p0 and p/p0 on the grid (a column each) for plotting.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
import gembem  # noqa: E402

COLUMNS = ("n", "code", "label", "status", "steps", "seed", "curve", "cpu", "wall", "mb", "force")


def read_runs(path):
    with open(path) as f:
        rows = [line.rstrip("\n").split("\t") for line in f]
    if not rows or tuple(rows[0]) != COLUMNS:
        sys.exit(f"shear_stats: {path}: expected the header {' '.join(COLUMNS)}")
    runs = []
    for k, r in enumerate(rows[1:], start=2):
        if len(r) != len(COLUMNS):
            sys.exit(f"shear_stats: {path}:{k}: {len(r)} fields, expected {len(COLUMNS)}")
        runs.append(dict(zip(COLUMNS, r)))
    return runs


def read_curve(run):
    """e1, s1, s2 arrays from a gembem steps.csv or a LAMMPS curve.txt; None if absent or empty.
    gembem's steps.csv also gives the load steps' work counts."""
    try:
        if run["code"] == "gembem":
            g = gembem.read_csv(run["curve"])
            load = g["step"] > 0
            run["work"] = {k: g[k][load].astype(float) for k in ("iterations", "sweeps", "factorisations")}
            run["cut"] = int(np.sum(g["substeps"][load] > 1)) if "substeps" in g else 0
            rows = list(zip(g["e1"], g["s1"], g["s2"]))
        else:
            with open(run["curve"]) as f:  # columns step, e1, e2, s1, s2
                rows = [(v[1], v[3], v[4]) for v in (line.split() for line in f if line[:1].isdigit())]
    except (OSError, KeyError, ValueError, IndexError):
        return None
    if not rows:
        return None
    a = np.array(rows, dtype=float)
    return a[:, 0], a[:, 1], a[:, 2]


def normalised(curve, grid):
    """q/p0 and p/p0 on the grid, p0, and whether the curve covers the grid."""
    e1, s1, s2 = curve
    q, p = 0.5 * (s1 - s2), 0.5 * (s1 + s2)
    p0 = p[0]
    covered = e1[0] <= grid[0] + 1e-12 and e1[-1] >= grid[-1] - 1e-9 and np.all(np.diff(e1) > 0)
    if not covered or p0 <= 0:
        return None, None, p0, False
    return np.interp(grid, e1, q) / p0, np.interp(grid, e1, p) / p0, p0, True


def pct(a, b):
    """(a - b) / |b| in per cent, formatted; '-' if either is missing."""
    if a is None or b is None or b == 0:
        return "-"
    return f"{100 * (a - b) / abs(b):+.1f} %"


def counts(work, key):
    v = work[key]
    if v.size == 0:
        return "-"
    return f"{v.mean():.1f} / {np.median(v):g} / {v.max():g}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("runs")
    ap.add_argument("--curves")
    ap.add_argument("--strain", type=float, default=0.05)
    ap.add_argument("--every", type=float, default=0.0025)
    a = ap.parse_args()
    npts = int(round(a.strain / a.every))
    if npts < 1 or abs(npts * a.every - a.strain) > 1e-9 * a.strain:
        sys.exit("shear_stats: --strain must be a whole multiple of --every")
    grid = a.every * np.arange(0, npts + 1)
    runs = read_runs(a.runs)
    for r in runs:
        r["q"] = r["p"] = r["p0"] = None
        r["ok"] = False
        c = read_curve(r)
        if c is not None:
            q, p, r["p0"], r["ok"] = normalised(c, grid)
            if r["ok"]:
                r["q"], r["p"] = q, p
                r["mq"], r["mp"] = q[1:].mean(), p[1:].mean()
    mean = lambda r, k: r[k] if r["ok"] else None

    lammps = [r for r in runs if r["code"] == "lammps"]
    seeds = sorted({r["seed"] for r in lammps}, key=lambda s: int(s))
    main_seed = seeds[0] if seeds else None
    rates = sorted((r for r in lammps if r["seed"] == main_seed), key=lambda r: int(r["steps"]))
    slowest = rates[-1] if rates else None

    print(f"Constant-volume biaxial shear to e1 = {100 * a.strain:g} % (e2 = -e1), q = (s1 - s2)/2 and "
          f"p = (s1 + s2)/2 over each run's start p0, at every {100 * a.every:g} % of e1; path means over "
          f"the {npts} points past the start; LAMMPS's slowest: "
          f"{slowest['label'] if slowest else 'none'}")
    print("| N | shear: code | status | work a load step, mean / median / max (gembem) or time steps (LAMMPS) "
          "| loading CPU s | wall s | peak MB | final largest force, checker [dyn] | start p0 [dyn/cm] "
          "| path mean q/p0 | path mean p/p0 | q/p0, p/p0 at the end | path means (q, p) off LAMMPS's slowest "
          "| LAMMPS CPU s / this CPU s (LAMMPS's time steps: ratio) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in runs:
        if r["code"] == "gembem" and "work" in r:
            work = (f"Newton {counts(r['work'], 'iterations')}; smoother steps {counts(r['work'], 'sweeps')}; "
                    f"factorisations {counts(r['work'], 'factorisations')}")
            if r["cut"]:
                work += f"; {r['cut']} load step{'s' if r['cut'] > 1 else ''} cut back"
        elif r["code"] == "gembem":
            work = "-"
        else:
            work = f"{int(r['steps']):,}".replace(",", " ") + f" (seed {r['seed']})"
        p0 = f"{r['p0']:.6g}" if r["p0"] is not None else "-"
        mq = f"{r['mq']:.4f}" if r["ok"] else "-"
        mp = f"{r['mp']:.4f}" if r["ok"] else "-"
        end = f"{r['q'][-1]:.4f}, {r['p'][-1]:.4f}" if r["ok"] else "-"
        off = "-"
        if r["ok"] and slowest is not None and slowest["ok"] and r is not slowest:
            off = f"{pct(r['mq'], slowest['mq'])}, {pct(r['mp'], slowest['mp'])}"
        ratio = ""
        if r["code"] == "gembem":
            try:
                cpu = float(r["cpu"])
                ratio = "; ".join(f"{int(l['steps'])}: {float(l['cpu']) / cpu:.2f}" for l in rates
                                  if l["ok"] and cpu > 0)
            except ValueError:
                pass
        print(f"| {r['n']} | {r['label']} | {r['status']} | {work} | {r['cpu']} | {r['wall']} | {r['mb']} "
              f"| {r['force']} | {p0} | {mq} | {mp} | {end} | {off} | {ratio or '-'} |")

    print()
    lines = []
    done = [r for r in rates if r["ok"]]
    if len(done) >= 2 and slowest["ok"]:
        for k, name in (("mq", "q"), ("mp", "p")):
            v = [r[k] for r in done]
            lines.append(f"LAMMPS's spread between rates (seed {main_seed}), path mean {name}/p0: {min(v):.4f} to "
                         f"{max(v):.4f}, {100 * (max(v) - min(v)) / abs(slowest[k]):.1f} % of the slowest's")
        for r in done[:-1]:
            twice = [t for t in done if int(t["steps"]) == 2 * int(r["steps"])]
            if twice:
                t = twice[0]
                lines.append(f"LAMMPS at {r['steps']} time steps against {t['steps']} (half its rate): path means "
                             f"q {pct(r['mq'], t['mq'])}, p {pct(r['mp'], t['mp'])}")
    for r in lammps:
        if r["seed"] == main_seed or not r["ok"]:
            continue
        twin = [t for t in rates if t["steps"] == r["steps"] and t["ok"]]
        if not twin:
            continue
        t = twin[0]
        dq = np.abs(r["q"] - t["q"])[1:]
        k = int(np.argmax(dq))
        lines.append(f"LAMMPS's repeat at {r['steps']} time steps, seed {r['seed']} against seed {t['seed']}: path means "
                     f"q {pct(r['mq'], t['mq'])}, p {pct(r['mp'], t['mp'])}; q/p0 differs by up to "
                     f"{dq[k]:.4f} ({100 * dq[k] / abs(t['mq']):.0f} % of the path mean of q) at e1 = {100 * grid[k + 1]:g} %, "
                     f"p/p0 by up to {np.abs(r['p'] - t['p'])[1:].max():.4f}")
    for r in runs:
        if r["code"] == "gembem" and r["ok"] and slowest is not None and slowest["ok"]:
            lines.append(f"{r['label']}: path means off LAMMPS's slowest ({slowest['steps']} time steps): "
                         f"q {pct(r['mq'], slowest['mq'])}, p {pct(r['mp'], slowest['mp'])}")
    for line in lines:
        print(f"- {line}")

    if a.curves:
        cols = [r for r in runs if r["ok"]]
        with open(a.curves, "w") as f:
            f.write(",".join(["e1"] + [f"{r['label']} {x}/p0" for r in cols for x in ("q", "p")]) + "\n")
            for i, e in enumerate(grid):
                f.write(",".join([f"{e:.6g}"] + [f"{r[x][i]:.8g}" for r in cols for x in ("q", "p")]) + "\n")


if __name__ == "__main__":
    main()
