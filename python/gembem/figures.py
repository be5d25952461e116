"""The standard figures of a run directory, with matplotlib.

Each function draws into ``ax`` (a new figure when None), saves to ``path`` when given, and
returns the matplotlib Figure. Figures are made with matplotlib.figure.Figure, not pyplot: no
global backend or figure list is touched, so they work headless (Agg) and in notebooks alike.
"""
import numpy as np
from matplotlib.collections import LineCollection, PatchCollection
from matplotlib.figure import Figure
from matplotlib.patches import Circle, Rectangle

from .rundir import Run
from .vtk import read_vtk


def _axes(ax, size=(6, 4.5), **kw):
    if ax is not None:
        return ax.figure, ax
    fig = Figure(figsize=size, layout="constrained")
    return fig, fig.add_subplot(**kw)


def _done(fig, path, dpi=120):
    if path is not None:
        fig.savefig(path, dpi=dpi)
    return fig


def _runs(runs):
    """One run or several, as Run objects (a path is opened)."""
    if isinstance(runs, (Run, str)) or hasattr(runs, "__fspath__"):
        runs = [runs]
    return [r if isinstance(r, Run) else Run(r) for r in runs]


def _host_segments(run):
    """The host's boundary elements as segments (from host_boundary.csv), or None without a host."""
    try:
        b = run.host_boundary
    except FileNotFoundError:
        return None
    half = 0.5 * b["length"]
    tx, ty = -b["ny"], b["nx"]
    return np.stack([np.stack([b["x"] - half * tx, b["y"] - half * ty], 1),
                     np.stack([b["x"] + half * tx, b["y"] + half * ty], 1)], 1)


def force_chains(run, step=None, ax=None, path=None, max_width=6.0, title=None):
    """Grains as circles and contacts as lines between the contact's two points, of width
    proportional to the normal force (the largest: max_width points); walls or the host's
    boundary in grey. step None: the final state; else contacts/ of that step."""
    run = _runs(run)[0]
    fig, ax = _axes(ax, size=(6, 6))
    g, c = run.grains(step), run.contacts(step)
    ax.add_collection(PatchCollection([Circle((x, y), r) for x, y, r in zip(g["x"], g["y"], g["r"])],
                                      facecolor="0.93", edgecolor="0.55", linewidths=0.5))
    if c.nrows:
        pn = np.asarray(c["pn"], dtype=float)
        top = pn.max() if pn.max() > 0 else 1.0
        segs = np.stack([np.stack([c["xi"], c["yi"]], 1), np.stack([c["xj"], c["yj"]], 1)], 1)
        ax.add_collection(LineCollection(segs, linewidths=max_width * np.clip(pn, 0, None) / top, colors="k",
                                         capstyle="round"))
    host = _host_segments(run) if step is None else None
    if host is not None:
        ax.add_collection(LineCollection(host, colors="0.4", linewidths=1.0))
    elif step is None and run.state.box:
        b = run.state.box
        ax.add_patch(Rectangle((b["left"], b["bottom"]), b["right"] - b["left"], b["top"] - b["bottom"],
                               fill=False, edgecolor="0.4", lw=1.0))
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    where = "final state" if step is None else f"step {step}"
    ax.set_title(title or f"force chains, {where}\n(line width proportional to the normal force, "
                          f"largest {c['pn'].max() if c.nrows else 0:.4g})", fontsize=9)
    return _done(fig, path)


def stress_strain(runs, x="e1_minus_e2", y="stress_ratio", labels=None, stages=None, ax=None, path=None):
    """A column of steps.csv against a strain column (drawn in per cent), one line per run.
    stages: only the steps of these loading stages (e.g. [2]: the shear after a preparation)."""
    runs = _runs(runs)
    fig, ax = _axes(ax)
    for k, run in enumerate(runs):
        s = run.steps
        if stages is not None:
            s = s.select(np.isin(s["stage"], stages))
        ax.plot(100 * s[x], s[y], marker="o", ms=2.5, lw=1.2,
                label=labels[k] if labels else run.path)
    ax.set_xlabel(f"{x} [%]")
    ax.set_ylabel(y)
    ax.grid(alpha=0.3)
    if len(runs) > 1 or labels:
        ax.legend(fontsize=8)
    return _done(fig, path)


def loaded_group(run):
    """The boundary group and axis ('x' or 'y') of a hybrid run that its loading drives: the
    largest |change of mean displacement| x |change of force| over the run (host_steps.csv);
    None when no group's displacement and force both change (a fixed body, an unbounded one)."""
    h = run.host_steps
    best, pick = 0.0, None
    for g in sorted(set(h["group"]) - {"cavity"}):
        rows = h.select(h["group"] == g)
        for axis in ("x", "y"):
            u, f = rows["u" + axis], rows["f" + axis]
            work = abs(u[-1] - u[0]) * abs(f[-1] - f[0])
            if work > best:
                best, pick = work, (g, axis)
    return pick


def load_displacement(runs, group=None, component=None, labels=None, ax=None, path=None):
    """A hybrid run's load-displacement curve from host_steps.csv: the force the outside puts on
    a boundary group against its mean displacement along x or y, both negated when the group
    is pushed in the negative direction, so that the loading curve rises. group and component
    None: those of loaded_group (of the first run)."""
    runs = _runs(runs)
    fig, ax = _axes(ax)
    if group is None or component is None:
        pick = loaded_group(runs[0])
        if pick is None:
            raise ValueError(f"{runs[0].path}: no boundary group is loaded (its displacement and force both "
                             "changing); expected group= and component=")
        group, component = group or pick[0], component or pick[1]
    for k, run in enumerate(runs):
        every = run.host_steps
        h = every.select(every["group"] == group)
        if not h.nrows:
            raise ValueError(f"{h.path}: no group '{group}'; its groups are {', '.join(sorted(set(every['group'])))}")
        u, f = h["u" + component], h["f" + component]
        sign = -1.0 if (u[-1] - u[0]) < 0 else 1.0
        ax.plot(sign * u, sign * f, marker="o", ms=2.5, label=labels[k] if labels else run.path)
    sign = "-" if sign < 0 else ""
    ax.set_xlabel(f"{sign}u{component}: mean displacement of '{group}'")
    ax.set_ylabel(f"{sign}f{component}: force on '{group}'")
    ax.grid(alpha=0.3)
    if len(runs) > 1 or labels:
        ax.legend(fontsize=8)
    return _done(fig, path)


def convergence(runs, step, labels=None, accuracy=None, ax=None, path=None):
    """The largest fixing force at the start of each iteration of one load step (history.csv,
    all its attempts in order), then the force it converged at (steps.csv), log scale; the
    accuracy as a dashed line (default: the a the first run solved that step to, steps.csv)."""
    runs = _runs(runs)
    fig, ax = _axes(ax)
    for k, run in enumerate(runs):
        h = run.history
        force = list(h["max_fixing_force"][h["step"] == step])
        if not force:
            raise ValueError(f"{h.path}: no iteration of step {step} (a step converged at once has none)")
        force += list(run.steps["max_fixing_force"][run.steps["step"] == step])
        label = labels[k] if labels else run.path
        ax.semilogy(np.arange(1, len(force) + 1), force, marker="o", ms=3,
                    label=f"{label} ({len(force) - 1} iterations)")
    if accuracy is None:  # the a the step was solved to (a relative accuracy resolves per step)
        steps = runs[0].steps
        rows = steps["accuracy"][steps["step"] == step] if "accuracy" in steps else []
        accuracy = float(rows[0]) if len(rows) else None
    if accuracy:
        ax.axhline(accuracy, color="k", lw=0.8, ls="--", label=f"accuracy {accuracy:g}")
    ax.set_xlabel("iteration of the load step")
    ax.set_ylabel("largest fixing force at its start")
    ax.set_title(f"convergence of load step {step}", fontsize=10)
    ax.legend(fontsize=8)
    return _done(fig, path)


def rose(run, step, column="count", ax=None, path=None):
    """Contact directions at a step (contacts/rose_NNNNNN.csv: 10-degree sectors, a grain-grain
    contact counted in n and -n), as a polar bar chart in per cent of the total."""
    run = _runs(run)[0]
    fig, ax = _axes(ax, size=(4.5, 4.5), projection="polar")
    r = run.rose(step)
    v = np.asarray(r[column], dtype=float)
    total = v.sum() if v.sum() > 0 else 1.0
    width = np.radians(r["to_deg"] - r["from_deg"])
    ax.bar(np.radians(r["from_deg"]) + width / 2, 100 * v / total, width=width, edgecolor="k", color="0.8")
    ax.set_title(f"contact {column} by direction, step {step} [%]", fontsize=10)
    return _done(fig, path)


def strain_map(run, step, quantity="gamma", ax=None, path=None, cmap="inferno", vmax=None):
    """The strain increment of one load step on the triangulation of the grain centres
    (fields/triangles_NNNNNN.vtu: cell data gamma, ev, exx, eyy, exy, rotation; compression
    positive), the grains at the step's end outlined, the step's localisation index in the title."""
    run = _runs(run)[0]
    fig, ax = _axes(ax, size=(6.5, 5.5))
    m = read_vtk(run.step_file("fields", "triangles", step, "vtu"))
    if quantity not in m.cell_data:
        raise ValueError(f"{m.path}: no cell data '{quantity}'; it has {', '.join(m.cell_data)}")
    tri = m.triangles()
    pc = ax.tripcolor(m.points[:, 0], m.points[:, 1], tri, facecolors=m.cell_data[quantity], cmap=cmap,
                      vmax=vmax, edgecolors="none")
    fig.colorbar(pc, ax=ax, label=f"{quantity} in step {step}")
    g = run.field("grains", step)
    r = run.state.grains["r"]    # radii do not change; the state lists the grains in the same order
    ax.add_collection(PatchCollection([Circle((x, y), rr) for x, y, rr in zip(g["x"], g["y"], r[g["grain"]])],
                                      facecolor="none", edgecolor="0.6", linewidths=0.4))
    host = _host_segments(run)
    if host is not None:
        ax.add_collection(LineCollection(host, colors="0.4", linewidths=0.8))
    ax.set_aspect("equal")
    ax.autoscale_view()
    loc = run.localisation
    index = loc["localisation_index"][loc["step"] == step]
    ax.set_title(f"{quantity} of step {step} on the centres' triangles"
                 + (f", localisation index {index[0]:.3f}" if len(index) else ""), fontsize=10)
    return _done(fig, path)


def host_stress(run, component="von_mises_inplane", ax=None, path=None, grains=True, cmap="viridis"):
    """The host's stress field at the end (host_field.vtu, tension positive) over its mesh, the
    grains' force chains of the final state drawn on top."""
    run = _runs(run)[0]
    fig, ax = _axes(ax, size=(6.5, 5.5))
    m = run.host_field()
    if component not in m.point_data:
        raise ValueError(f"{m.path}: no point data '{component}'; it has {', '.join(m.point_data)}")
    pc = ax.tripcolor(m.points[:, 0], m.points[:, 1], m.triangles(), m.point_data[component],
                      shading="gouraud", cmap=cmap)
    fig.colorbar(pc, ax=ax, label=component)
    if grains:
        force_chains(run, ax=ax, title="")
    ax.set_aspect("equal")
    ax.set_title(f"host {component} at the end, with the grains' force chains", fontsize=10)
    return _done(fig, path)
