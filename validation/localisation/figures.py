#!/usr/bin/python3
"""Figures and the sweep table of the localisation study, from runs/localisation (Snakefile).

  strain_maps.png       the base case at chosen steps: grains' accumulated shear strain since the
                        top started to move (triangles on the centres), the host's shear strain on
                        the ring around the cavity, and at the last step the host's whole field
  strain_maps_sweep.png the same at the last completed step for every case
  localisation_index.png the localisation index of every step against the top's displacement
  concentration.png     hoop stress / reference stress along the cavity wall at the last step:
                        empty cavity, elastic discs, grains
  load_displacement.png the top's force against its displacement, every case and the references
  sweep.md              the table of the README (peak index, load at localisation, concentration)

Usage: validation/localisation/figures.py [RUNS_DIR]   (from anywhere; PNGs next to this file)
       validation/localisation/figures.py --episodes NAME ...   the band episodes of extended cases
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import yaml  # noqa: E402
from matplotlib.collections import PatchCollection  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
import gembem  # noqa: E402
import study  # noqa: E402
from gembem.figures import index_of  # noqa: E402  (the localisation index as the run computes it)

RUNS = (sys.argv[1] if len(sys.argv) > 1 and not sys.argv[1].startswith("--")
        else os.path.join(HERE, "..", "..", "runs", "localisation"))
THRESHOLD = 0.5  # the localisation index of one step that marks "localised" in the table
WTHRESHOLD = 0.4  # the same for the windowed index


def read_csv(path):
    """gembem.read_csv with its integer columns as float64, as this script's arithmetic expects."""
    return {k: v.astype(float) if v.dtype.kind == "i" else v for k, v in gembem.read_csv(path).items()}


def status_line(case_dir, name):
    """How a run ended, as 'NAME exit RC SECONDS s MESSAGE': from the workflow's NAME.yaml
    (Snakefile), or the NAME.txt of the former run_study.sh; None if it did not run."""
    y, t = os.path.join(case_dir, name + ".yaml"), os.path.join(case_dir, name + ".txt")
    if os.path.exists(y):
        with open(y) as f:
            d = yaml.safe_load(f)
        return f"{d['case']} exit {d['exit']} {d['seconds']:.0f} s {d['message']}" if "exit" in d else None
    return open(t).read().strip() if os.path.exists(t) else None


class Case:
    def __init__(self, name, phi, friction, kn):
        self.name, self.phi, self.friction, self.kn = name, phi, friction, kn
        self.dir = os.path.join(RUNS, name)
        # The attempts: the run, and if it stopped, the one with the top's steps halved; the one
        # that converged (the first), else the one that got further.
        attempts = []
        for run, status, refine in [("run", "status", 1), ("run_refine2", "status_refine2", 2)]:
            rp, st = os.path.join(self.dir, run), status_line(self.dir, status)
            if os.path.exists(os.path.join(rp, "localisation.csv")) and st:
                hs = read_csv(os.path.join(rp, "host_steps.csv"))
                attempts.append((rp, st, refine, -hs["uy"][hs["group"] == "top"][-1]))
        self.attempts = attempts
        self.ok = bool(attempts)
        if not self.ok:
            self.status = ""
            return
        conv = [a for a in attempts if "exit 0" in a[1]]
        self.run, self.status, self.refine, _ = conv[0] if conv else max(attempts, key=lambda a: a[3])
        self.window = WINDOW * self.refine
        self.loc = read_csv(os.path.join(self.run, "localisation.csv"))
        self.steps = read_csv(os.path.join(self.run, "steps.csv"))
        hs = read_csv(os.path.join(self.run, "host_steps.csv"))
        top = hs["group"] == "top"
        self.top_uy, self.top_fy = -hs["uy"][top], -hs["fy"][top]
        self.last = int(self.loc["step"][-1])
        self.first_top = study.STEPS_P + 2  # the first step that moves the top (step 1 relaxes)
        self.radii = read_csv(os.path.join(self.dir, "grains.csv"))["r"]
        self.converged = "exit 0" in self.status

    def label(self):
        return (f"phi {self.phi:.2f}, {self.friction:.0f} deg, kn/G {self.kn / study.G:g} cm"
                + (f", steps / {self.refine}" if self.ok and self.refine > 1 else ""))

    def loading(self):
        """Steps of the top's loading and their top displacement."""
        s = self.loc["step"].astype(int)
        m = s >= self.first_top
        return s[m], self.top_uy[s[m]], self.loc["localisation_index"][m]


def field_path(case, kind, step):
    """fields/KIND_STEP.csv of a case's run (an extended case: of the segment holding the step)."""
    if hasattr(case, "segment_of"):
        run, local = case.segment_of(step)
        return os.path.join(run, "fields", f"{kind}_{local:06d}.csv")
    return os.path.join(case.run, "fields", f"{kind}_{step:06d}.csv")


def grains_at(case, step):
    return read_csv(field_path(case, "grains", step))


def accumulated_strain(case, k0, k1):
    """Shear strain accumulated from the start of step k0 to the end of step k1, per triangle of
    the centres at the start, triangles bridging a void of the largest diameter dropped."""
    a, b = grains_at(case, k0), grains_at(case, k1)
    x0, y0 = a["x0"], a["y0"]
    ux, uy = b["x"] - x0, b["y"] - y0
    r = case.radii
    tri = mtri.Triangulation(x0, y0)
    t = tri.triangles
    dmax = 2 * r.max()
    keep = np.ones(len(t), bool)
    for i, j in [(0, 1), (1, 2), (2, 0)]:
        p, q = t[:, i], t[:, j]
        keep &= np.hypot(x0[p] - x0[q], y0[p] - y0[q]) <= r[p] + r[q] + dmax
    tri.set_mask(~keep)
    X1, X2 = np.stack([x0[t[:, 1]] - x0[t[:, 0]], y0[t[:, 1]] - y0[t[:, 0]]], 1), np.stack(
        [x0[t[:, 2]] - x0[t[:, 0]], y0[t[:, 2]] - y0[t[:, 0]]], 1)
    U1, U2 = np.stack([ux[t[:, 1]] - ux[t[:, 0]], uy[t[:, 1]] - uy[t[:, 0]]], 1), np.stack(
        [ux[t[:, 2]] - ux[t[:, 0]], uy[t[:, 2]] - uy[t[:, 0]]], 1)
    Xm = np.stack([X1, X2], 2)  # columns: edge vectors
    Um = np.stack([U1, U2], 2)
    det = np.linalg.det(Xm)
    ok = keep & (np.abs(det) > 1e-12)
    H = np.zeros((len(t), 2, 2))
    H[ok] = Um[ok] @ np.linalg.inv(Xm[ok])
    E = 0.5 * (H + np.transpose(H, (0, 2, 1)) + np.transpose(H, (0, 2, 1)) @ H)
    gamma = 2 * np.sqrt((0.5 * (E[:, 0, 0] - E[:, 1, 1]))**2 + E[:, 0, 1]**2)
    area = 0.5 * np.abs(det)
    tri = mtri.Triangulation(b["x"], b["y"], triangles=t)  # drawn on the grains' positions at the end
    tri.set_mask(~ok)
    return tri, gamma, ok, area, b


def host_ring(case, step):
    h = read_csv(field_path(case, "host_ring", step))
    g = 2 * np.sqrt((0.5 * (h["exx"] - h["eyy"]))**2 + h["exy"]**2)
    return h["x"], h["y"], g


def host_field(case):
    """The host's whole field at the run's last step (host_field.vtu): points and shear strain."""
    m = gembem.read_vtk(os.path.join(case.run, "host_field.vtu"))
    pts = m.points
    sxx, syy, sxy = (m.point_data[k] for k in ("sxx", "syy", "sxy"))
    nu = getattr(case, "nu", study.NU)
    tr = sxx + syy
    exx, eyy, exy = (sxx - nu * tr) / (2 * study.G), (syy - nu * tr) / (2 * study.G), sxy / (2 * study.G)
    g = 2 * np.sqrt((0.5 * (exx - eyy))**2 + exy**2)
    return pts[:, 0], pts[:, 1], g


def draw_map(ax, case, k1, vmax_g, vmax_h, full_host=False):
    k0 = case.first_top
    tri, gamma, ok, area, b = accumulated_strain(case, k0, k1)
    if full_host:
        hx, hy, hg = host_field(case)
        m = np.hypot(hx, hy) > 2.5
        ax.tricontourf(hx[m], hy[m], hg[m], levels=np.linspace(0, vmax_h, 21), cmap="Greys", extend="max")
    rx, ry, rg = host_ring(case, k1)
    hs = ax.scatter(rx, ry, c=rg, cmap="Greys", vmin=0, vmax=vmax_h, s=28, marker="s", edgecolors="k",
                    linewidths=0.3)
    tp = ax.tripcolor(tri, facecolors=np.where(ok, gamma, 0), cmap="inferno", vmin=0, vmax=vmax_g)
    ax.add_collection(PatchCollection([Circle((x, y), r) for x, y, r in zip(b["x"], b["y"], case.radii)],
                                      facecolor="none", edgecolor="0.6", linewidths=0.25))
    ax.add_patch(Circle((0, 0), 2.5, fill=False, color="tab:blue", lw=0.8))
    ax.set_aspect("equal")
    ax.set_xlim(-4.6, 4.6), ax.set_ylim(-4.6, 4.6)
    ax.set_xticks([]), ax.set_yticks([])
    return tp, hs, index_of(np.where(ok, gamma, 0), np.where(ok, area, 0))


def base_case(cases):
    name = study.case_name(study.BASE["phi"], study.BASE["friction"], study.BASE["kn_g"])
    return next(c for c in cases if c.name == name)


def fig_strain_maps(cases):
    c = base_case(cases)
    if not c.ok or c.last < c.first_top:
        return
    n_load = c.last - c.first_top + 1
    chosen = sorted({c.first_top + max(0, round(f * n_load) - 1) for f in (0.25, 0.5, 0.75, 1.0)})
    _, gl, _, _, _ = accumulated_strain(c, c.first_top, c.last)
    vg = np.percentile(gl[gl > 0], 98)
    vh = np.max(host_ring(c, c.last)[2]) * 1.2
    n = len(chosen)
    fig = plt.figure(figsize=(3.2 * n + 1.6, 3.9))
    gs = fig.add_gridspec(1, n + 3, width_ratios=[1] * n + [0.05, 0.12, 0.05], wspace=0.08)
    for q, k in enumerate(chosen):
        ax = fig.add_subplot(gs[0, q])
        tp, hs, li = draw_map(ax, c, k, vg, vh, full_host=(k == c.last))
        ax.set_title(f"step {k}: top down {c.top_uy[k]:.3f} cm\naccumulated index {li:.2f}", fontsize=8)
    cb = fig.colorbar(tp, cax=fig.add_subplot(gs[0, n]))
    cb.set_label("grains: accumulated shear strain", fontsize=8)
    cb = fig.colorbar(hs, cax=fig.add_subplot(gs[0, n + 2]))
    cb.set_label("host: shear strain e1 - e2 (ring; last panel: whole field)", fontsize=8)
    fig.subplots_adjust(left=0.02, right=0.94, bottom=0.04, top=0.82, wspace=0.1)
    fig.suptitle(f"Base case ({c.label()}): grains' shear strain accumulated since the top started to move, on "
                 "their positions at the step; the host's total shear strain", fontsize=9)
    fig.savefig(os.path.join(HERE, "strain_maps.png"), dpi=130)
    plt.close(fig)


def fig_strain_maps_sweep(cases):
    done = [c for c in cases if c.ok and c.last >= c.first_top]
    if not done:
        return
    n = len(done)
    cols = min(4, n)
    rows = math.ceil(n / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(3.1 * cols + 0.8, 3.3 * rows))
    axes = np.atleast_1d(axes).ravel()
    for ax in axes[n:]:
        ax.axis("off")
    vh = max(np.max(host_ring(c, c.last)[2]) for c in done) * 1.2
    for ax, c in zip(axes, done):
        _, g, _, _, _ = accumulated_strain(c, c.first_top, c.last)
        vg = np.percentile(g[g > 0], 98)
        tp, hs, li = draw_map(ax, c, c.last, vg, vh)
        ax.set_title(f"{c.label()}\nstep {c.last} ({c.top_uy[c.last]:.3f} cm), index {li:.2f}"
                     f"{'' if c.converged else ', stopped'}", fontsize=7)
        fig.colorbar(tp, ax=ax, fraction=0.04, pad=0.01)
    fig.suptitle("Accumulated shear strain of the grains (own colour scale per panel, 98th percentile) "
                 "and the host's on the ring (common grey scale), last completed step; cavity outline and ring at rest",
                 fontsize=8)
    fig.savefig(os.path.join(HERE, "strain_maps_sweep.png"), dpi=120)
    plt.close(fig)


SWEEP_KEYS = [("friction", "grain friction", lambda c: c.friction, "{:.0f} deg"),
              ("phi", "solid fraction", lambda c: c.phi, "phi {:.2f}"),
              ("kn_g", "kn / G", lambda c: c.kn / study.G, "kn/G {:g} cm")]


def sweep_members(cases, key):
    b = study.BASE
    out = []
    for c in cases:
        vals = {"friction": c.friction, "phi": c.phi, "kn_g": c.kn / study.G}
        if all(abs(vals[k] - b[k]) < 1e-9 for k in b if k != key):
            out.append(c)
    return out


WINDOW = 10  # steps over which the windowed index accumulates the strain


def windowed_index(c):
    """The localisation index of the strain accumulated over the last WINDOW steps (of the full
    size: WINDOW x refine steps of a refined run), per step."""
    if not hasattr(c, "_win"):
        ks, vals = [], []
        for k in range(c.first_top + c.window - 1, c.last + 1, c.refine):
            _, g, ok, area, _ = accumulated_strain(c, k - c.window + 1, k)
            ks.append(k)
            vals.append(index_of(np.where(ok, g, 0), np.where(ok, area, 0)))
        c._win = (np.array(ks, int), np.array(vals))
    return c._win


def fig_index(cases):
    fig, axes = plt.subplots(2, 3, figsize=(13, 6.6), sharey="row", sharex=True)
    for q, (key, title, val, fmt) in enumerate(SWEEP_KEYS):
        for c in sweep_members(cases, key):
            if not c.ok:
                continue
            s, u, li = c.loading()
            lab = (fmt.format(val(c)) + (f", steps / {c.refine}" if c.refine > 1 else "")
                   + ("" if c.converged else f" (stopped at {c.top_uy[c.last]:.2f} cm)"))
            line, = axes[0, q].plot(u, li, "-", lw=0.8, label=lab)
            ks, wi = windowed_index(c)
            if len(ks):
                axes[1, q].plot(c.top_uy[ks], wi, "-", lw=1.2, color=line.get_color(), label=lab)
        for ax in axes[:, q]:
            ax.axhline(0.1, color="0.5", lw=0.6, ls=":")
            ax.legend(fontsize=7)
        axes[1, q].set_xlabel("top displacement [cm]")
        axes[0, q].set_title(f"sweep over {title}", fontsize=9)
    axes[0, 0].set_ylabel("index of the step's increment")
    axes[1, 0].set_ylabel(f"index of the strain over the last\n{-WINDOW * study.DUY:.2f} cm of the top's travel")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "localisation_index.png"), dpi=130)
    plt.close(fig)


def reference(name, step=None):
    """A reference's wall at the granular runs' step (the references have no relaxation step: their
    step k is the granular step k + 1; None: the last) and its curve."""
    p = os.path.join(RUNS, "reference", name)
    w, cv = read_csv(p + "_wall.csv"), read_csv(p + "_curve.csv")
    k = int(w["step"].max()) if step is None else step - 1
    m = w["step"] == k
    return {key: v[m] for key, v in w.items()}, cv


def fig_concentration(cases):
    fig, axes = plt.subplots(1, 3, figsize=(13, 4), sharey=True)
    discs = [(n, g) for n, g, _ in study.disc_moduli()]
    final = study.STEPS_P + study.STEPS + 1  # the granular runs' last step
    for ax, (key, title, val, fmt) in zip(axes, SWEEP_KEYS):
        empty, _ = reference("empty", final)
        o = np.argsort(empty["angle_deg"])
        ax.plot(empty["angle_deg"][o], empty["concentration"][o], "k-", lw=1.4, label="empty cavity (BEM)")
        for n, g in discs:
            if n != "homogeneous" and not (key == "kn_g" or n == f"voigt_k{study.BASE['kn_g']:g}"):
                continue
            w, _ = reference("disc_" + n, final)
            o = np.argsort(w["angle_deg"])
            lab = "disc G_d = G (homogeneous)" if n == "homogeneous" else f"Voigt disc G_d/G = {g / study.G:.3g}"
            ax.plot(w["angle_deg"][o], w["concentration"][o], "--", lw=1, label=lab)
        for c in sweep_members(cases, key):
            if not c.ok:
                continue
            w = read_csv(os.path.join(c.run, "fields", f"host_wall_{c.last:06d}.csv"))
            ang = np.degrees(np.arctan2(w["y"], w["x"]))
            o = np.argsort(ang)
            ax.plot(ang[o], w["concentration"][o], "o-", ms=2, lw=0.8,
                    label="grains, " + fmt.format(val(c)) + f" (step {c.last})")
        ax.set_xlabel("angle on the cavity wall from +x [deg]")
        ax.set_xticks(range(-180, 181, 90))
        ax.set_title(f"sweep over {title}: references at step {final} (top {-study.DUY * study.STEPS:.2f} cm)",
                     fontsize=8)
        ax.legend(fontsize=6)
    axes[0].set_ylabel("hoop stress / reference stress (tension +)")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "concentration.png"), dpi=130)
    plt.close(fig)


def fig_load(cases):
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    discs = study.disc_moduli()
    greys = plt.cm.Greys(np.linspace(0.35, 0.8, len(discs)))
    for (n, lab, st), col in zip([("empty", "empty cavity (BEM)", "-")] + [
            ("disc_" + n, ("disc G_d = G" if n == "homogeneous" else f"Voigt disc G_d/G = {g / study.G:.3g}"), "--")
            for n, g, _ in discs], [(0, 0, 0, 1)] + list(greys)):
        _, cv = reference(n)
        ax.plot(-cv["top_uy"], -cv["top_fy"], st, color=col, lw=1.1, label=lab)
    done = [c for c in cases if c.ok]
    for c, col in zip(done, plt.cm.turbo(np.linspace(0.05, 0.95, len(done)))):
        ax.plot(c.top_uy, c.top_fy, "-", color=col, lw=1.0, label=c.label() + ("" if c.converged else " (stopped)"))
    ax.set_xlabel("top displacement [cm]")
    ax.set_ylabel("force on the top [kgf per cm of depth]")
    ax.legend(fontsize=6)
    ax.set_title("Load-displacement of the body (confining pressure first, top held)", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "load_displacement.png"), dpi=130)
    plt.close(fig)


def table(cases):
    lines = ["| case | steps done | peak index of a step (step, top [cm]) | "
             f"first step with index >= {THRESHOLD} (top [cm], s_ref [kgf/cm^2]) | "
             f"peak windowed index (step, top [cm]) | first windowed index >= {WTHRESHOLD} "
             "(step, top [cm], s_ref) | index of the whole loading | largest concentration (step) | "
             "top force / empty cavity's at the last step |",
             "|---|---|---|---|---|---|---|---|---|"]
    for c in cases:
        if not c.ok:
            lines.append(f"| {c.label()} | no output | | | | | | | |")
            continue
        s, u, li = c.loading()
        if len(s) == 0:
            lines.append(f"| {c.label()} | stopped before the top moved: {c.status} | | | | | | | |")
            continue
        k = int(np.argmax(li))
        over = np.nonzero(li >= THRESHOLD)[0]
        first = (f"{s[over[0]]} ({u[over[0]]:.3f}, {c.loc['s_ref'][s[over[0]]]:.0f})" if len(over) else "never")
        _, g, ok, area, _ = accumulated_strain(c, c.first_top, c.last)
        acc = index_of(np.where(ok, g, 0), np.where(ok, area, 0))
        ks, wi = windowed_index(c)
        win = f"{wi.max():.2f} ({ks[int(np.argmax(wi))]}, {c.top_uy[ks[int(np.argmax(wi))]]:.2f})" if len(ks) else "-"
        wfirst = np.nonzero(wi >= WTHRESHOLD)[0] if len(ks) else []
        wload = (f"{ks[wfirst[0]]} ({c.top_uy[ks[wfirst[0]]]:.2f}, {c.loc['s_ref'][ks[wfirst[0]]]:.0f})"
                 if len(wfirst) else "never")
        mc = c.loc["max_concentration"][c.first_top:]
        j = int(np.argmax(np.abs(mc)))
        done = f"{c.last}" + ("" if c.converged else f" (stopped: step {c.last + 1} did not converge)")
        _, ecv = reference("empty")
        ratio = c.top_fy[c.last] / np.interp(c.top_uy[c.last], -ecv["top_uy"][study.STEPS_P:],
                                              -ecv["top_fy"][study.STEPS_P:])
        lines.append(f"| {c.label()} | {done} | {li[k]:.2f} ({s[k]}, {u[k]:.2f}) | {first} | {win} | {wload} | "
                     f"{acc:.2f} | {mc[j]:.2f} ({c.first_top + j}) | {ratio:.3f} |")
    refs = []
    _, ecv = reference("empty")
    for n, lab in [("empty", "empty cavity")] + [("disc_" + n, f"disc G_d/G = {g / study.G:.3g}, nu {nu:.3g}")
                                                   for n, g, nu in study.disc_moduli()]:
        _, cv = reference(n)
        refs.append(f"| {lab} | {cv['max_concentration'][-1]:.3f} | {-cv['top_fy'][-1]:.0f} | "
                    f"{cv['top_fy'][-1] / ecv['top_fy'][-1]:.3f} |")
    with open(os.path.join(HERE, "sweep.md"), "w") as f:
        f.write("\n".join(lines) + "\n\n| reference (BEM alone) | largest concentration at the last step | "
                "force on the top at the last step [kgf/cm] | / empty cavity's |\n|---|---|---|---|\n" + "\n".join(refs) + "\n")



# ---------------------------------------------------------------------------------------------
# Extended cases (study.py EXTENDED, run by run_continued.py in segments)

EXT_WINDOW = 0.1   # cm of the top's travel over which the windowed index accumulates the strain
EXT_EVERY = 0.02   # cm of travel between windows' ends
TOP_SHARE = 0.1    # the most strained share of the grains compared between successive windows


class ExtCase:
    """An extended case: its segments stitched into one numbering of steps (segment 0's own; a
    later segment's step j > 0 is the step first + j, its step 0 the previous segment's last)."""

    def __init__(self, name, c):
        self.name, self.c = name, c
        self.nu = c["nu"]
        self.ok = False
        at = os.path.join(RUNS, name, "attempt.txt")
        if os.path.exists(at):
            self.dir = os.path.join(RUNS, name, open(at).read().strip())
            self.refine = int(self.dir[-1:])  # attemptK: K = the step divisor (run_continued.py ATTEMPTS)
        else:  # a run of the first run_continued.py (one attempt, its segments in NAME/)
            self.dir, self.refine = os.path.join(RUNS, name), 1
        sp = os.path.join(self.dir, "segments.csv")
        if not os.path.exists(sp):
            return
        seg = read_csv(sp)
        self.segments = []
        for k in range(len(seg["segment"])):
            run = os.path.join(self.dir, f"seg{int(seg['segment'][k]):02d}")
            if int(seg["steps"][k]) > 0 or k == 0:
                self.segments.append((run, int(seg["first_step"][k]), int(seg["steps"][k])))
        self.seg = seg
        self.status = open(os.path.join(self.dir, "status.txt")).read().strip()
        self.converged = "exit 0" in self.status
        self.radii = read_csv(os.path.join(self.dir, "grains.csv"))["r"]
        self.first_top = study.STEPS_P + 2
        # travel, top force, localisation rows per global step
        trav, force, rows = [], [], {}
        for q, (run, first, n) in enumerate(self.segments):
            hs = read_csv(os.path.join(run, "host_steps.csv"))
            top = hs["group"] == "top"
            st = hs["step"][top].astype(int)
            shear = c["load"] == "shear"
            u = np.abs(hs["ux"][top] if shear else hs["uy"][top])
            f = np.abs(hs["fx"][top] if shear else hs["fy"][top])
            lo = read_csv(os.path.join(run, "localisation.csv"))
            for j in range(len(st)):
                if q > 0 and st[j] == 0:
                    continue
                trav.append(u[j]), force.append(f[j])
            for key, v in lo.items():
                rows.setdefault(key, []).extend(list(v if q == 0 else v[lo["step"] > 0]))
        self.top_uy, self.top_fy = np.array(trav), np.array(force)
        self.loc = {k: np.array(v) for k, v in rows.items()}
        self.loc["step"] = np.arange(len(self.loc["step"]))
        self.last = len(self.top_uy) - 1
        self.run = self.segments[-1][0]
        self.ok = self.last >= self.first_top

    def segment_of(self, k):
        for run, first, n in reversed(self.segments):
            if k >= first:
                return run, k - first
        raise ValueError(k)

    def label(self):
        c = self.c
        return (f"{self.name}: {c['load']}, {c['n']} grains, kn/G {c['kn_g']:g} cm, nu {c['nu']:g}, "
                f"P {c['P']:g}" + (f", steps / {self.refine}" if self.refine > 1 else ""))

    def loading(self):
        s = self.loc["step"]
        m = s >= self.first_top
        return s[m], self.top_uy[s[m]], self.loc["localisation_index"][m]

    def start_of_window(self, k, width):
        """The step whose start is `width` cm of travel before the end of step k."""
        t0 = self.top_uy[k] - width
        j = int(np.searchsorted(self.top_uy, t0 + 1e-9))  # first step ending beyond t0
        return max(self.first_top, j)

    def window_ends(self, width=EXT_WINDOW, every=EXT_EVERY):
        out, nxt = [], width
        for k in range(self.first_top, self.last + 1):
            if self.top_uy[k] >= nxt - 1e-9:
                out.append(k)
                nxt = self.top_uy[k] + every
        return out


STRIP = 0.5  # cm: the width of the straight strip of the band measure


def strip_share(tri, gamma, ok, area, width=STRIP, step=0.05, offset=False, dang=5):
    """The band measure: the largest share of sum(gamma area) in a straight strip `width` cm wide
    across the zone (any direction, `dang` degree steps; triangles by their centroids), with the
    strip's share of the area and the direction of the strip's axis (degrees from +x). A uniform
    field gives the area share (about 0.13 for a strip through the centre); a band crossing the
    zone several times that."""
    t = tri.triangles
    cx, cy = tri.x[t].mean(1), tri.y[t].mean(1)
    wg, wa = np.where(ok, gamma * area, 0), np.where(ok, area, 0)
    tot, tota = wg.sum(), wa.sum()
    if tot <= 0:
        return (0.0, 0.0, 0.0, 0.0) if offset else (0.0, 0.0, 0.0)
    m = int(round(width / step))
    best = (0.0, 0.0, 0.0, 0.0)
    for ang in np.arange(0, 180, dang):
        th = math.radians(ang)
        pr = -cx * math.sin(th) + cy * math.cos(th)  # distance across a strip along direction ang
        edges = np.arange(pr.min() - 1e-9, pr.max() + step, step)
        hg, _ = np.histogram(pr, edges, weights=wg)
        ha, _ = np.histogram(pr, edges, weights=wa)
        cg = np.convolve(hg, np.ones(m), "valid")
        ca = np.convolve(ha, np.ones(m), "valid")
        j = int(np.argmax(cg))
        if cg[j] / tot > best[0]:
            best = (cg[j] / tot, ca[j] / tota, float(ang), edges[j] + width / 2)
    return best if offset else best[:3]


PROFILE_D = 1.0  # mean grain diameters: the strips of the profile contrast (about one grain row)
BAND_D = 8.0     # mean grain diameters: the strip of the band measure in d (a shear band's thickness)


def profile_contrast(tri, gamma, ok, area, width, dang=1):
    """The band network measure: across each direction (`dang` degree steps; triangles by their
    centroids) the profile of the area-weighted mean strain in strips `width` wide, its contrast
    std / mean over the strips at least half as long as the longest (weighted by their area).
    Bands parallel to a direction, one or a network of them, make its profile peak at each band;
    a field without order has a contrast that falls as the strips hold more triangles.
    Returns (the largest contrast, its direction [deg from +x], the contrast per direction)."""
    t = tri.triangles
    c = contrast_per_direction(tri.x[t].mean(1)[ok], tri.y[t].mean(1)[ok], (gamma * area)[ok], area[ok], width, dang)
    j = int(np.argmax(c))
    return float(c[j]), float(j * dang), c


def contrast_per_direction(cx, cy, wg, wa, width, dang=1):
    """profile_contrast's contrast per direction (0, dang, ... < 180 deg) of the points (cx, cy)
    carrying strain x area wg and area wa."""
    angs = np.arange(0, 180, dang)
    if wg.sum() <= 0:
        return np.zeros(len(angs))
    c = np.empty(len(angs))
    for i, ang in enumerate(angs):
        th = math.radians(ang)
        pr = -cx * math.sin(th) + cy * math.cos(th)   # across the direction, as strip_share
        b = ((pr - pr.min()) / width).astype(int)
        sg, sa = np.bincount(b, wg), np.bincount(b, wa)
        # the strips at least half as long as the longest: the window's thin ends left out (a
        # sliver's huge strain on the edge makes its short strip's mean anything)
        k = sa >= 0.5 * sa.max()
        mean = sg[k].sum() / sa[k].sum()
        var = np.sum(sg[k]**2 / sa[k]) / sa[k].sum() - mean**2   # sum_i a_i (m_i - mean)^2 / sum a_i
        c[i] = math.sqrt(max(var, 0.0)) / mean if mean > 0 else 0.0
    return c


def second_direction(c, dang=1, apart=30):
    """The largest of the contrasts per direction `c` at least `apart` degrees from the largest
    (directions modulo 180): a conjugate family's direction, and that contrast."""
    angs = np.arange(len(c)) * dang
    j = int(np.argmax(c))
    sep = np.abs(angs - angs[j]) % 180
    far = np.minimum(sep, 180 - sep) >= apart
    k = int(np.nonzero(far)[0][np.argmax(c[far])])
    return float(angs[k]), float(c[k])


def grain_strain(case, k0, k1):
    """Per grain: the area-weighted mean of the accumulated shear strain of its triangles."""
    tri, gamma, ok, area, b = accumulated_strain(case, k0, k1)
    n = len(case.radii)
    num, den = np.zeros(n), np.zeros(n)
    w = np.where(ok, area, 0)
    for v in range(3):
        np.add.at(num, tri.triangles[:, v], np.where(ok, gamma, 0) * w)
        np.add.at(den, tri.triangles[:, v], w)
    return np.where(den > 0, num / np.maximum(den, 1e-300), 0), den > 0


def ext_windows(c):
    """Per window end (every EXT_EVERY cm): the step, the travel, the windowed index, and the share
    of the most strained TOP_SHARE of the grains of this window that were among those of the
    window just before it (ending where this one starts; 0.1 if unrelated)."""
    if hasattr(c, "_w"):
        return c._w
    ks, tr, wi, ov, ss, sa = [], [], [], [], [], []
    for k in c.window_ends():
        k0 = c.start_of_window(k, EXT_WINDOW)
        tri, g, ok, area, _ = accumulated_strain(c, k0, k)
        ks.append(k), tr.append(c.top_uy[k])
        wi.append(index_of(np.where(ok, g, 0), np.where(ok, area, 0)))
        sh, _, ang = strip_share(tri, g, ok, area)
        ss.append(sh), sa.append(ang)
        prev = k0 - 1
        if prev >= c.first_top and c.top_uy[prev] - c.top_uy[c.first_top - 1] >= EXT_WINDOW - 1e-9:
            ga, oka = grain_strain(c, k0, k)
            gb, okb = grain_strain(c, c.start_of_window(prev, EXT_WINDOW), prev)
            m = oka & okb
            nt = max(1, int(round(TOP_SHARE * m.sum())))
            idx = np.nonzero(m)[0]
            ta = set(idx[np.argsort(-ga[m])[:nt]])
            tb = set(idx[np.argsort(-gb[m])[:nt]])
            ov.append(len(ta & tb) / nt)
        else:
            ov.append(np.nan)
    c._w = tuple(np.array(v) for v in (ks, tr, wi, ov, ss, sa))
    return c._w


def wall_nonaffine(run):
    """The cavity wall's displacement at the run's last step (host_particles.csv) less its best
    affine fit u = c + B x (x: the element midpoints at rest): rms residual over rms of u - mean(u)."""
    h = read_csv(os.path.join(run, "host_particles.csv"))
    X = np.stack([np.ones_like(h["x"]), h["x"], h["y"]], 1)
    res = 0.0
    dev = 0.0
    for u in (h["ux"], h["uy"]):
        coef, *_ = np.linalg.lstsq(X, u, rcond=None)
        res += np.sum((u - X @ coef)**2)
        dev += np.sum((u - u.mean())**2)
    return math.sqrt(res / dev), math.sqrt(res / len(h["x"]))


def wall_text(run):
    share, rms = wall_nonaffine(run)
    return f"{share:.3f} ({rms * 1e4:.0f})"


def grains_nonaffine(c):
    """The same for the grains' displacement since the top started to move (step first_top's start
    to the last step), positions at the start: how far the zone's motion is from affine."""
    a, b = grains_at(c, c.first_top), grains_at(c, c.last)
    X = np.stack([np.ones_like(a["x0"]), a["x0"], a["y0"]], 1)
    res = dev = 0.0
    for u in (b["x"] - a["x0"], b["y"] - a["y0"]):
        coef, *_ = np.linalg.lstsq(X, u, rcond=None)
        res += np.sum((u - X @ coef)**2)
        dev += np.sum((u - u.mean())**2)
    return f"{math.sqrt(res / dev):.3f} ({math.sqrt(res / len(a['x0'])) * 1e4:.0f})"


def shrink_png(path):
    """A PNG of many small maps in 256 colours (the figures' files stay below 400 KB)."""
    from PIL import Image
    Image.open(path).convert("RGB").quantize(256).save(path, optimize=True)


def ext_cases():
    return [ExtCase(n, c) for n, c in study.extended()]


def fig_ext_index(ecs):
    done = [c for c in ecs if c.ok]
    if not done:
        return
    fig, axes = plt.subplots(3, 1, figsize=(8, 9.5), sharex=True)
    cols = plt.cm.tab20(np.arange(len(done)) % 20)
    for c, col in zip(done, cols):
        ks, tr, wi, ov, ss, sa = ext_windows(c)
        lab = c.name + ("" if c.converged else f" (stopped at {c.top_uy[c.last]:.2f} cm)")
        axes[0].plot(tr, wi, "-", color=col, lw=1.1, label=lab)
        axes[1].plot(tr, ss, "-", color=col, lw=1.0, label=lab)
        axes[2].plot(tr, ov, "-", color=col, lw=1.0, label=lab)
    axes[0].axhline(0.5, color="0.4", lw=0.7, ls="--")
    axes[0].axhline(0.1, color="0.5", lw=0.6, ls=":")
    axes[2].axhline(TOP_SHARE, color="0.5", lw=0.6, ls=":")
    axes[0].set_ylabel(f"index of the strain over the last\n{EXT_WINDOW:g} cm of the top's travel")
    axes[1].set_ylabel(f"share of that strain in the best\nstraight strip {STRIP:g} cm wide")
    axes[1].axhline(0.13, color="0.5", lw=0.6, ls=":")
    axes[2].set_ylabel(f"share of the most strained {TOP_SHARE:.0%} of the grains\n"
                       "that were so in the window before")
    axes[2].set_xlabel("top's travel [cm] (biaxial: down; shear: sideways)")
    axes[0].legend(fontsize=7, ncol=2)
    axes[0].set_title("Extended cases: windowed localisation index (top), band measure (middle; dotted: a uniform "
                      f"field's), persistence of the most strained grains between successive {EXT_WINDOW:g} cm "
                      f"windows (bottom; dotted: no memory)", fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "extended_index.png"), dpi=110)
    plt.close(fig)
    shrink_png(os.path.join(HERE, "extended_index.png"))


def fig_ext_maps(ecs):
    """Per case: the strain of five successive-in-time windows spread over the travel, and the
    strain accumulated over the whole loading."""
    done = [c for c in ecs if c.ok]
    if not done:
        return
    ncol = 6
    fig, axes = plt.subplots(len(done), ncol, figsize=(2.0 * ncol + 0.4, 2.2 * len(done)))
    axes = np.atleast_2d(axes)
    for row, c in zip(axes, done):
        ends = c.window_ends()
        pick = [ends[int(round(q))] for q in np.linspace(0, len(ends) - 1, ncol - 1)] if ends else []
        panels = [(c.start_of_window(k, EXT_WINDOW), k) for k in pick] + [(c.first_top, c.last)]
        for ax, (k0, k1) in zip(row, panels):
            _, g, _, _, _ = accumulated_strain(c, k0, k1)
            vg = np.percentile(g[g > 0], 98) if np.any(g > 0) else 1
            tri, gamma, ok, area, b = accumulated_strain(c, k0, k1)
            ax.tripcolor(tri, facecolors=np.where(ok, gamma, 0), cmap="inferno", vmin=0, vmax=vg)
            ax.add_patch(Circle((0, 0), 2.5, fill=False, color="tab:blue", lw=0.6))
            ax.set_aspect("equal"), ax.set_xlim(-3.2, 3.2), ax.set_ylim(-3.6, 2.8)
            ax.set_xticks([]), ax.set_yticks([])
            li = index_of(np.where(ok, gamma, 0), np.where(ok, area, 0))
            whole = (k0, k1) == (c.first_top, c.last)
            ax.set_title(("whole loading" if whole else f"{c.top_uy[k0 - 1]:.2f}-{c.top_uy[k1]:.2f} cm")
                         + f": {li:.2f}", fontsize=7)
        row[0].set_ylabel(c.name, fontsize=7)
        for ax in row[len(panels):]:
            ax.axis("off")
    fig.suptitle(f"Extended cases: grains' shear strain over {EXT_WINDOW:g} cm windows of the top's travel and over "
                 "the whole loading (own scale per panel: 98th percentile); title: travel, index", fontsize=8)
    fig.tight_layout(rect=(0, 0, 1, 0.98))
    fig.savefig(os.path.join(HERE, "extended_maps.png"), dpi=70)
    plt.close(fig)
    shrink_png(os.path.join(HERE, "extended_maps.png"))


def fig_ext_windows(c, ncol=7, most=14):
    """One case: the strain of successive windows of EXT_WINDOW cm over the whole travel (all of
    them if at most `most`, else `most` spread evenly), each on its own colour scale."""
    ends = c.window_ends(EXT_WINDOW, EXT_WINDOW)
    if not ends:
        return
    if len(ends) > most:
        ends = [ends[int(round(q))] for q in np.linspace(0, len(ends) - 1, most)]
    rows = math.ceil(len(ends) / ncol)
    fig, axes = plt.subplots(rows, ncol, figsize=(1.9 * ncol, 2.0 * rows + 0.4))
    axes = np.atleast_1d(axes).ravel()
    for ax in axes[len(ends):]:
        ax.axis("off")
    for ax, k in zip(axes, ends):
        k0 = c.start_of_window(k, EXT_WINDOW)
        tri, gamma, ok, area, b = accumulated_strain(c, k0, k)
        g = gamma[ok]
        vg = np.percentile(g[g > 0], 98) if np.any(g > 0) else 1
        ax.tripcolor(tri, facecolors=np.where(ok, gamma, 0), cmap="inferno", vmin=0, vmax=vg)
        ax.add_patch(Circle((0, 0), 2.5, fill=False, color="tab:blue", lw=0.6))
        ax.set_aspect("equal"), ax.set_xlim(-3.6, 3.6), ax.set_ylim(-3.6, 3.0)
        ax.set_xticks([]), ax.set_yticks([])
        li = index_of(np.where(ok, gamma, 0), np.where(ok, area, 0))
        ax.set_title(f"{c.top_uy[k0 - 1]:.2f}-{c.top_uy[k]:.2f} cm: {li:.2f}", fontsize=7)
    fig.suptitle(f"{c.label()}: grains' shear strain over successive {EXT_WINDOW:g} cm windows of the top's travel "
                 "(own scale per panel, 98th percentile; title: travel, index)", fontsize=7)
    fig.tight_layout(rect=(0, 0, 1, 0.96))
    fig.savefig(os.path.join(HERE, f"extended_windows_{c.name}.png"), dpi=75)
    plt.close(fig)
    shrink_png(os.path.join(HERE, f"extended_windows_{c.name}.png"))


def ext_table(ecs):
    lines = ["| case | loading, grains, kn/G [cm], nu, P [kgf/cm^2] | travel reached / asked [cm] | segments "
             "(stalls), seconds | windowed index: peak (travel) | windows >= 0.5 | median windowed index, "
             "second half of the travel | band measure: median, second half (peak, travel, strip direction) | "
             "persistence of the top 10 % (median) | index of the whole loading | band measure of the whole "
             "loading (direction; the strip's share of the area) | wall non-affine share (rms, um) | grains non-affine share (rms, um) |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for c in ecs:
        p = c.c
        desc = f"{p['load']}, {p['n']}, {p['kn_g']:g}, {p['nu']:g}, {p['P']:g}"
        if not c.ok:
            lines.append(f"| {c.name} | {desc} | no output | | | | | | | | | | |")
            continue
        ks, tr, wi, ov, ss, sa = ext_windows(c)
        tri, g, ok, area, _ = accumulated_strain(c, c.first_top, c.last)
        whole = index_of(np.where(ok, g, 0), np.where(ok, area, 0))
        wss, warea, wang = strip_share(tri, g, ok, area)
        sec = tr >= tr[-1] / 2
        half = wi[sec]
        js = int(np.argmax(ss))
        segs = len(c.seg["segment"])
        stalls = int(np.sum(c.seg["exit"] == 3))
        secs = float(np.sum(c.seg["seconds"]))
        j = int(np.argmax(wi)) if len(wi) else 0
        lines.append(f"| {c.name} | {desc} | {c.top_uy[c.last]:.2f} / {p['du'] * p['steps']:g} | {segs} ({stalls}), "
                     f"{secs:.0f} | {wi.max():.2f} ({tr[j]:.2f}) | {int(np.sum(wi >= 0.5))} of {len(wi)} | "
                     f"{np.median(half):.2f} | {np.median(ss[sec]):.2f} ({ss[js]:.2f}, {tr[js]:.2f}, {sa[js]:.0f}) | "
                     f"{np.nanmedian(ov):.2f} | {whole:.2f} | {wss:.2f} ({wang:.0f}; {warea:.2f}) | {wall_text(c.run)} | "
                     f"{grains_nonaffine(c)} |")
    # the sweep's attempts, for comparison
    with open(os.path.join(HERE, "extended.md"), "w") as f:
        f.write("\n".join(lines) + "\n")


def sweep_nonaffine(cases):
    """The wall's and the grains' non-affine shares of the sweep's cases, and the empty cavity's wall
    at the same travel (reference/empty_wall.csv)."""
    out = []
    w = read_csv(os.path.join(RUNS, "reference", "empty_wall.csv"))
    _, cv = reference("empty")
    for c in cases:
        if not c.ok:
            continue
        k = int(np.argmin(np.abs(-cv["top_uy"] - c.top_uy[c.last])))
        m = w["step"] == k
        X = np.stack([np.ones(m.sum()), w["x"][m], w["y"][m]], 1)
        res = dev = 0.0
        for u in (w["ux"][m], w["uy"][m]):
            coef, *_ = np.linalg.lstsq(X, u, rcond=None)
            res += np.sum((u - X @ coef)**2)
            dev += np.sum((u - u.mean())**2)
        tri, g, ok, area, _ = accumulated_strain(c, c.first_top, c.last)
        wss, warea, wang = strip_share(tri, g, ok, area)
        wins = [strip_share(*accumulated_strain(c, k - c.window + 1, k)[:4])[0]
                for k in range(c.first_top + c.window - 1, c.last + 1, c.refine)]
        out.append(f"| {c.label()} | {c.top_uy[c.last]:.2f} | {wss:.2f} ({wang:.0f}; {warea:.2f}) | "
                   f"{np.median(wins) if wins else 0:.2f} ({max(wins) if wins else 0:.2f}) | "
                   f"{wall_text(c.run)} | {math.sqrt(res / dev):.3f} ({math.sqrt(res / m.sum()) * 1e4:.0f}) | "
                   f"{grains_nonaffine(c)} |")
    return ("| case | top [cm] | band measure of the whole loading (strip direction, deg; the strip's share of the area) | band measure over "
            "0.1 cm windows: median (peak) | wall non-affine share (rms, um) | empty cavity's wall, same travel | "
            "grains non-affine share (rms, um) |\n|---|---|---|---|---|---|---|\n" + "\n".join(out) + "\n")


EPISODE = 0.45  # band measure of a window that counts as a band


def band_episodes(c):
    """The spans of travel over which the band measure of the 0.1 cm windows stays >= EPISODE:
    (travel at the end of the first and of the last such window, its peak, the strip direction)."""
    ks, tr, wi, ov, ss, sa = ext_windows(c)
    out, j = [], 0
    while j < len(ss):
        if ss[j] >= EPISODE:
            e = j
            while e + 1 < len(ss) and ss[e + 1] >= EPISODE:
                e += 1
            p = j + int(np.argmax(ss[j:e + 1]))
            offs = []  # where the strip lies: its axis' signed distance from the cavity's centre at rest
            for q in range(j, e + 1):
                k = int(ks[q])
                tri, g, ok, area, _ = accumulated_strain(c, c.start_of_window(k, EXT_WINDOW), k)
                offs.append(strip_share(tri, g, ok, area, offset=True)[3])
            out.append((tr[j], tr[e], ss[p], sa[p], sa[j:e + 1], offs))
            j = e + 1
        else:
            j += 1
    return out


def print_episodes(names):
    """figures.py --episodes NAME ...: the band episodes of extended cases (no figure drawn)."""
    for n, cfg in study.extended():
        if n not in names:
            continue
        c = ExtCase(n, cfg)
        for t0, t1, peak, ang, angs, offs in band_episodes(c):
            print(f"{n}: band measure >= {EPISODE} from the window ending at {t0:.2f} cm to the one ending at "
                  f"{t1:.2f} cm (windows {EXT_WINDOW:g} cm wide, ends every {EXT_EVERY:g} cm); peak {peak:.2f} "
                  f"along {ang:.0f} deg; directions {sorted(set(int(a) for a in angs))}; strip axis "
                  f"{min(offs):.2f} to {max(offs):.2f} cm from the centre")


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--episodes":
        print_episodes(sys.argv[2:])
        return
    cases = [Case(*c) for c in study.cases()]
    fig_strain_maps(cases)
    fig_strain_maps_sweep(cases)
    fig_index(cases)
    fig_concentration(cases)
    fig_load(cases)
    table(cases)
    with open(os.path.join(HERE, "sweep.md"), "a") as f:
        f.write("\n" + sweep_nonaffine(cases))
    print(open(os.path.join(HERE, "sweep.md")).read())
    ecs = ext_cases()
    fig_ext_index(ecs)
    fig_ext_maps(ecs)
    for c in ecs:
        if c.ok and c.name in study.EXT_WINDOW_MAPS:
            fig_ext_windows(c)
    ext_table(ecs)
    print(open(os.path.join(HERE, "extended.md")).read())


if __name__ == "__main__":
    main()
