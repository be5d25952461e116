#!/usr/bin/python3
"""Figures and the sweep table of the localisation study, from runs/localisation (run_study.sh).

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
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PatchCollection  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import study  # noqa: E402

RUNS = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "..", "..", "runs", "localisation")
THRESHOLD = 0.5  # the localisation index of one step that marks "localised" in the table
WTHRESHOLD = 0.4  # the same for the windowed index


def read_csv(path):
    with open(path) as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))]
    head, body = rows[0], rows[1:]
    out = {}
    for k, name in enumerate(head):
        col = [r[k] for r in body]
        try:
            out[name] = np.array([float(v) for v in col])
        except ValueError:
            out[name] = np.array(col)
    return out


class Case:
    def __init__(self, name, phi, friction, kn):
        self.name, self.phi, self.friction, self.kn = name, phi, friction, kn
        self.dir = os.path.join(RUNS, name)
        # The attempts: the run, and if it stopped, the one with the top's steps halved; the one
        # that converged (the first), else the one that got further.
        attempts = []
        for run, status, refine in [("run", "status.txt", 1), ("run_refine2", "status_refine2.txt", 2)]:
            rp, sp = os.path.join(self.dir, run), os.path.join(self.dir, status)
            if os.path.exists(os.path.join(rp, "localisation.csv")) and os.path.exists(sp):
                st = open(sp).read().strip()
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


def grains_at(case, step):
    return read_csv(os.path.join(case.run, "fields", f"grains_{step:06d}.csv"))


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


def index_of(gamma, area):
    """The localisation index of a field: share of sum(gamma area) in the most strained 10 %."""
    o = np.argsort(-gamma)
    g, a = gamma[o], area[o]
    total, want, acc, part = np.sum(g * a), 0.1 * np.sum(a), 0.0, 0.0
    for gi, ai in zip(g, a):
        take = min(ai, want - acc)
        if take <= 0:
            break
        part += gi * take
        acc += take
    return part / total if total > 0 else 0


def host_ring(case, step):
    p = os.path.join(case.run, "fields", f"host_ring_{step:06d}.csv")
    h = read_csv(p)
    g = 2 * np.sqrt((0.5 * (h["exx"] - h["eyy"]))**2 + h["exy"]**2)
    return h["x"], h["y"], g


def host_field(case):
    """The host's whole field at the run's last step (host_field.vtu): points and shear strain."""
    text = open(os.path.join(case.run, "host_field.vtu")).read()

    def array(name):
        key = f'Name="{name}"' if name else 'NumberOfComponents="3" format="ascii">'
        i = text.index(key)
        i = text.index(">", i) + 1
        j = text.index("</DataArray>", i)
        return np.array(text[i:j].split(), float)

    i = text.index("<Points>")
    j = text.index("</DataArray>", i)
    pts = np.array(text[text.index(">", text.index("<DataArray", i)) + 1:j].split(), float).reshape(-1, 3)
    sxx, syy, sxy = array("sxx"), array("syy"), array("sxy")
    nu = study.NU
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


def main():
    cases = [Case(*c) for c in study.cases()]
    fig_strain_maps(cases)
    fig_strain_maps_sweep(cases)
    fig_index(cases)
    fig_concentration(cases)
    fig_load(cases)
    table(cases)
    print(open(os.path.join(HERE, "sweep.md")).read())


if __name__ == "__main__":
    main()
