"""The standard figures of a run directory, with matplotlib.

Each function draws into ``ax`` (a new figure when None), saves to ``path`` when given, and
returns the matplotlib Figure. Figures are made with matplotlib.figure.Figure, not pyplot: no
global backend or figure list is touched, so they work headless (Agg) and in notebooks alike.
"""
import os

import numpy as np
from matplotlib.collections import LineCollection, PatchCollection
from matplotlib.figure import Figure
from matplotlib.patches import Circle, Polygon, Rectangle
from matplotlib.path import Path
from matplotlib.tri import Triangulation

from .library import Simulation
from .rundir import Packing, Run
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
    """One run or several, as Run objects (a path is opened; a Packing is kept, for the figures of
    a final state; a gembem.Simulation too, for the figures of its steps)."""
    if isinstance(runs, (Run, Packing, Simulation, str)) or hasattr(runs, "__fspath__"):
        runs = [runs]
    return [r if isinstance(r, (Run, Packing, Simulation)) else Run(r) for r in runs]


def _host_segments(run, displaced=False):
    """The host's boundary elements as segments (from host_boundary.csv), or None without that file;
    displaced: where they are at the end of the run (where the final state's grains are), each
    element's end points moved by the mean displacement of the elements that share them."""
    try:
        b = run.host_boundary
    except (FileNotFoundError, AttributeError):   # a box run; a packing (its host has no files)
        return None
    half = 0.5 * b["length"]
    tx, ty = -b["ny"], b["nx"]
    ends = np.stack([np.stack([b["x"] - half * tx, b["y"] - half * ty], 1),
                     np.stack([b["x"] + half * tx, b["y"] + half * ty], 1)], 1)
    if not displaced:
        return ends
    tol = 1e-6 * max(np.ptp(b["x"]), np.ptp(b["y"]), 1e-300)
    keys = np.round(ends.reshape(-1, 2) / tol).astype(np.int64)
    _, node = np.unique(keys, axis=0, return_inverse=True)
    node = node.reshape(-1)
    u = np.repeat(np.stack([b["ux"], b["uy"]], 1), 2, axis=0)          # each end: its element's u
    mean = np.zeros((node.max() + 1, 2))
    np.add.at(mean, node, u)
    mean /= np.bincount(node)[:, None]
    return ends + mean[node].reshape(-1, 2, 2)


def _inside_body(b, segs, points):
    """Which points lie in the host's body: inside its outer loop (if it has one) and outside
    its other loops (cavities). b: host_boundary.csv; segs: its elements' segments, in order
    along each loop. A loop is outer when the body's outward normals point away from its centre."""
    inside = np.ones(len(points), bool)
    for loop in np.unique(b["loop"]):
        k = b["loop"] == loop
        poly = Path(segs[k, 0])
        mid = segs[k].mean(axis=1)
        outer = np.sum(b["nx"][k] * (mid[:, 0] - mid[:, 0].mean()) + b["ny"][k] * (mid[:, 1] - mid[:, 1].mean())) > 0
        within = poly.contains_points(points)
        inside &= within if outer else ~within
    return inside


def _boundary_stress(run, component):
    """A component of the host's stress on each boundary element at the end (host_boundary.csv),
    or None when that file has no such component."""
    b = run.host_boundary
    if component in ("sxx", "syy", "sxy"):
        return b[component]
    if component == "von_mises_inplane":
        sxx, syy, sxy = b["sxx"], b["syy"], b["sxy"]
        return np.sqrt(sxx * sxx - sxx * syy + syy * syy + 3 * sxy * sxy)
    return None


def _units(run):
    """The scene's (length, force) unit names, or ("", "") when it gives none."""
    u = run.scene.get("units") or {}
    return u.get("length", ""), u.get("force", "")


def _stress_unit(run):
    """A 2D stress's unit: force per length^2 (per unit thickness of the plane)."""
    length, force = _units(run)
    return f"{force}/{length}^2" if length and force else ""


def _zone_limits(ax, x, y, r, margin=0.08):
    """Axes limits around discs (x, y, r), with a margin of `margin` of the extent."""
    x0, x1, y0, y1 = np.min(x - r), np.max(x + r), np.min(y - r), np.max(y + r)
    m = margin * max(x1 - x0, y1 - y0)
    ax.set_xlim(x0 - m, x1 + m)
    ax.set_ylim(y0 - m, y1 + m)


def force_chains(run, step=None, ax=None, path=None, max_width=6.0, title=None, outline=True):
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
    host = _host_segments(run, displaced=True) if step is None and outline else None
    if host is not None:
        ax.add_collection(LineCollection(host, colors="0.4", linewidths=1.0))
    elif step is None and outline and run.state.host_particles is not None:   # a packing's cavity: no host files
        p = run.state.host_particles
        ax.add_patch(Polygon(np.stack([p["x"], p["y"]], 1), closed=True, fill=False, edgecolor="0.4", lw=1.0))
    elif step is None and outline and run.state.box:
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


def size_distribution(run, ax=None, path=None):
    """The grains' radii of the final state (a run's or a packing's) as cumulative distributions,
    by number and by area (the share of grains, or of the grains' area, of at most each radius)."""
    run = _runs(run)[0]
    fig, ax = _axes(ax)
    r = np.sort(np.asarray(run.state.grains["r"], dtype=float))
    share = np.arange(1, len(r) + 1) / max(len(r), 1)
    ax.step(r, 100 * share, where="post", label="by number")
    ax.step(r, 100 * np.cumsum(r * r) / max(np.sum(r * r), 1e-300), where="post", label="by area")
    length = _units(run)[0]
    ax.set_xlabel(f"radius [{length}]" if length else "radius")
    ax.set_ylabel("grains of at most this radius [%]")
    ax.set_title(f"grain sizes: {len(r)} grains, radii {r[0]:.4g} to {r[-1]:.4g}" if len(r) else "no grains",
                 fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return _done(fig, path)


def force_distribution(run, step=None, bins=30, ax=None, path=None):
    """The normal contact forces over their mean (force-carrying contacts, pn > 0) as a probability
    density, log scale: the exponential tail of a jammed packing's forces shows as a straight line.
    step None: the final state; else contacts/ of that step."""
    run = _runs(run)[0]
    fig, ax = _axes(ax)
    pn = np.asarray(run.contacts(step)["pn"], dtype=float)
    pn = pn[pn > 0]
    if len(pn):
        f = pn / pn.mean()
        density, edges = np.histogram(f, bins=bins, density=True)
        mid = 0.5 * (edges[:-1] + edges[1:])
        ax.semilogy(mid[density > 0], density[density > 0], marker="o", ms=3, lw=1.0)
    ax.set_xlabel("normal force / mean normal force")
    ax.set_ylabel("probability density")
    where = "final state" if step is None else f"step {step}"
    ax.set_title(f"contact force distribution, {where}: {len(pn)} contacts, mean {pn.mean() if len(pn) else 0:.4g}",
                 fontsize=10)
    ax.grid(alpha=0.3, which="both")
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
        force = iteration_forces(run, step)
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


def iteration_forces(run, step):
    """The largest fixing force at the start of each iteration of one load step (history.csv, all
    its attempts in order), then the force it converged at (steps.csv), as an array."""
    run = _runs(run)[0]
    h = run.history
    rows = h["step"] == step
    if "smoother" in h:  # the iterations' rows, not the smoother's progress within them
        rows = rows & (h["smoother"] == 0)
    force = list(h["max_fixing_force"][rows])
    if not force:
        raise ValueError(f"{h.path}: no iteration of step {step} (a step converged at once has none)")
    force += list(run.steps["max_fixing_force"][run.steps["step"] == step])
    return np.array(force, dtype=float)


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


def index_of(gamma, area, fraction=0.1):
    """The localisation index of a strain field (docs/measures.md): the share of sum(gamma x area)
    carried by the most strained `fraction` of the area, triangles sorted by gamma, the last one
    counted in part; 0.1 for a uniform field, 0 when nothing shears."""
    gamma, area = np.asarray(gamma, float), np.asarray(area, float)
    total = np.sum(gamma * area)
    if not total > 0:
        return 0.0
    o = np.argsort(-gamma, kind="stable")
    g, a = gamma[o], area[o]
    before = np.concatenate([[0.0], np.cumsum(a)[:-1]])          # area taken before each triangle
    take = np.clip(fraction * a.sum() - before, 0, a)
    return float(np.sum(g * take) / total)


def accumulated_strain(run, since, step):
    """The strain accumulated from the start of load step `since` to the end of `step`, on the
    triangles of `since`'s field (fields/triangles_NNNNNN.vtu: the grain centres at its start,
    triangles bridging a void dropped), as the run computes a step's (Green-Lagrange, compression
    positive): a dict of arrays per triangle (gamma, ev, exx, eyy, exy, area at the start) and
    `triangles` (m x 3 grain indices), `x`, `y` (the centres at the end of `step`) and `index`,
    the field's localisation index."""
    run = _runs(run)[0]
    tri = read_vtk(run.step_file("fields", "triangles", since, "vtu")).triangles()
    a, b = run.field("grains", since), run.field("grains", step)
    if not (np.array_equal(a["grain"], np.arange(len(a["grain"])))
            and np.array_equal(b["grain"], a["grain"])):
        raise ValueError(f"{run.path}: fields/grains_{since:06d}.csv and _{step:06d}.csv do not list the grains "
                         "0, 1, ... in order")
    x0, y0, x1, y1 = a["x0"], a["y0"], b["x"], b["y"]
    e1, e2 = tri[:, 1], tri[:, 2]
    D = np.stack([np.stack([x0[e1] - x0[tri[:, 0]], x0[e2] - x0[tri[:, 0]]], 1),
                  np.stack([y0[e1] - y0[tri[:, 0]], y0[e2] - y0[tri[:, 0]]], 1)], 1)     # edges (columns)
    ux, uy = x1 - x0, y1 - y0
    U = np.stack([np.stack([ux[e1] - ux[tri[:, 0]], ux[e2] - ux[tri[:, 0]]], 1),
                  np.stack([uy[e1] - uy[tri[:, 0]], uy[e2] - uy[tri[:, 0]]], 1)], 1)
    H = U @ np.linalg.inv(D)
    E = 0.5 * (H + np.transpose(H, (0, 2, 1)) + np.transpose(H, (0, 2, 1)) @ H)
    exx, eyy, exy = -E[:, 0, 0], -E[:, 1, 1], -E[:, 0, 1]
    gamma = 2 * np.sqrt((0.5 * (exx - eyy))**2 + exy**2)
    area = 0.5 * np.abs(np.linalg.det(D))
    return {"gamma": gamma, "ev": exx + eyy, "exx": exx, "eyy": eyy, "exy": exy, "area": area,
            "triangles": tri, "x": x1, "y": y1, "index": index_of(gamma, area)}


def strain_map(run, step, quantity="gamma", since=None, ax=None, path=None, cmap="inferno", vmax=None,
               zoom=None, title=None):
    """The strain on the triangulation of the grain centres, the grains at the end of `step`
    outlined: the increment of that one load step (fields/triangles_NNNNNN.vtu: cell data gamma,
    ev, exx, eyy, exy, rotation; compression positive) with the step's localisation index from
    localisation.csv in the title; or with `since`, the strain accumulated from the start of step
    `since` to the end of `step` (accumulated_strain) and its index. vmax None: the 99th percentile.
    zoom (default: with a host) limits the axes to the granular zone."""
    run = _runs(run)[0]
    fig, ax = _axes(ax, size=(6.5, 5.5))
    if since is None:
        m = read_vtk(run.step_file("fields", "triangles", step, "vtu"))
        if quantity not in m.cell_data:
            raise ValueError(f"{m.path}: no cell data '{quantity}'; it has {', '.join(m.cell_data)}")
        x, y, tri, values = m.points[:, 0], m.points[:, 1], m.triangles(), m.cell_data[quantity]
        loc = run.localisation
        index = loc["localisation_index"][loc["step"] == step]
        index = index[0] if len(index) else None
        what = f"{quantity} of step {step}"
    else:
        acc = accumulated_strain(run, since, step)
        if quantity not in acc:
            raise ValueError(f"no accumulated '{quantity}'; expected gamma, ev, exx, eyy or exy")
        x, y, tri, values, index = acc["x"], acc["y"], acc["triangles"], acc[quantity], acc["index"]
        what = f"{quantity} from step {since} to {step}"
    if vmax is None and len(values):
        vmax = float(np.percentile(values, 99)) or None
    pc = ax.tripcolor(x, y, tri, facecolors=values, cmap=cmap, vmax=vmax, edgecolors="none")
    fig.colorbar(pc, ax=ax, label=what + (" (compression +)" if quantity != "gamma" else ""), shrink=0.85)
    g = run.field("grains", step)
    r = run.state.grains["r"]    # radii do not change; the state lists the grains in the same order
    ax.add_collection(PatchCollection([Circle((x, y), rr) for x, y, rr in zip(g["x"], g["y"], r[g["grain"]])],
                                      facecolor="none", edgecolor="0.6", linewidths=0.4))
    last = int(run.steps["step"][-1])
    host = _host_segments(run, displaced=(step == last))
    if host is not None:
        ax.add_collection(LineCollection(host, colors="0.4", linewidths=0.8))
    ax.set_aspect("equal")
    ax.autoscale_view()
    if zoom or (zoom is None and host is not None):
        _zone_limits(ax, g["x"], g["y"], r[g["grain"]])
    ax.set_title(title or (what + " on the centres' triangles"
                           + (f"\nlocalisation index {index:.3f} (0.1: uniform)" if index is not None else "")),
                 fontsize=10)
    return _done(fig, path)


def localisation_index(run, ax=None, path=None, x=None, stages=None, label=None):
    """The localisation index of every load step's increment (localisation.csv) against the
    displacement of the group the loading drives (loaded_group; host runs) or the step number;
    stages: only these loading stages' steps."""
    run = _runs(run)[0]
    fig, ax = _axes(ax)
    loc, s = run.localisation, run.steps
    keep = np.isin(s["step"], loc["step"]) & (s["step"] > 0)
    if stages is not None:
        keep &= np.isin(s["stage"], stages)
    steps = s["step"][keep]
    index = np.array([loc["localisation_index"][loc["step"] == k][0] for k in steps])
    pick = loaded_group(run) if x is None and os.path.exists(os.path.join(run.path, "host_steps.csv")) else None
    if pick is not None:
        group, axis = pick
        h = run.host_steps.select(run.host_steps["group"] == group)
        u = np.array([h["u" + axis][h["step"] == k][0] for k in steps])
        sign = -1.0 if h["u" + axis][-1] - h["u" + axis][0] < 0 else 1.0
        xs, xlabel = sign * u, f"{'-' if sign < 0 else ''}u{axis} of '{group}' [{_units(run)[0]}]"
    else:
        xs, xlabel = steps, "load step"
    ax.plot(xs, index, marker="o", ms=2.5, lw=1.0, label=label)
    ax.axhline(0.1, color="0.5", lw=0.7, ls=":")
    ax.text(xs[0] if len(xs) else 0, 0.1, " uniform strain", fontsize=7, va="bottom", color="0.4")
    ax.set_xlabel(xlabel)
    ax.set_ylabel("localisation index of the step")
    ax.set_ylim(0, max(0.6, 1.1 * index.max(initial=0)))
    ax.grid(alpha=0.3)
    return _done(fig, path)


def cavity_wall(run, steps, ax=None, path=None, labels=None):
    """The host's hoop stress along its cavity wall (fields/host_wall_NNNNNN.csv, tension
    positive) against the angle around the cavity's centre, at each of `steps`: with the grains
    (solid) and for the empty cavity under the same outer conditions (dashed, hoop_empty)."""
    run = _runs(run)[0]
    fig, ax = _axes(ax)
    unit = _stress_unit(run)
    for k, step in enumerate(steps):
        w = run.field("host_wall", step)
        cx, cy = np.mean(w["x"]), np.mean(w["y"])
        ang = np.degrees(np.arctan2(w["y"] - cy, w["x"] - cx)) % 360
        o = np.argsort(ang)
        lab = labels[k] if labels else f"step {step}"
        line, = ax.plot(ang[o], w["hoop"][o], lw=1.3, label=f"{lab}: with the grains")
        ax.plot(ang[o], w["hoop_empty"][o], lw=1.0, ls="--", color=line.get_color(), label=f"{lab}: empty cavity")
    ax.set_xlabel("angle around the cavity's centre [deg] (0: +x, 90: +y)")
    ax.set_ylabel(f"hoop stress on the cavity wall [{unit}] (tension +)" if unit else "hoop stress (tension +)")
    ax.set_xticks(range(0, 361, 45))
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return _done(fig, path)


def host_stress(run, component="von_mises_inplane", ax=None, path=None, grains=True, cmap="viridis",
                displaced=True, title=None, vmax=None):
    """The host's stress field at the end (host_field.vtu, tension positive), and on its boundary
    elements (host_boundary.csv, drawn as thick segments: the interior grid keeps away from the
    boundary), where the body is at the end (displaced: moved by the displacement), the grains'
    force chains of the final state on top. One colour scale for both (vmax None: the largest)."""
    run = _runs(run)[0]
    fig, ax = _axes(ax, size=(6.5, 5.5))
    m = run.host_field()
    if component not in m.point_data:
        raise ValueError(f"{m.path}: no point data '{component}'; it has {', '.join(m.point_data)}")
    xy = m.points[:, :2] + (m.point_data["displacement"][:, :2] if displaced else 0)
    values = m.point_data[component]
    edge = _boundary_stress(run, component)
    segs = _host_segments(run, displaced=displaced)
    if edge is not None:     # the grid keeps away from the boundary: the boundary's own stress closes the gap
        used = np.unique(m.triangles())
        b = run.host_boundary
        # the elements' midpoints with their values, their end points with the mean of the elements there
        ends = segs.reshape(-1, 2)
        keys = np.round(ends / (1e-6 * np.ptp(ends, axis=0).max())).astype(np.int64)
        _, first, node = np.unique(keys, axis=0, return_index=True, return_inverse=True)
        node = node.reshape(-1)
        at_end = np.bincount(node, weights=np.repeat(edge, 2)) / np.bincount(node)
        x = np.concatenate([xy[used, 0], segs.mean(axis=1)[:, 0], ends[first, 0]])
        y = np.concatenate([xy[used, 1], segs.mean(axis=1)[:, 1], ends[first, 1]])
        values = np.concatenate([values[used], edge, at_end])
        tri = Triangulation(x, y)
        cx, cy = x[tri.triangles].mean(axis=1), y[tri.triangles].mean(axis=1)
        tri.set_mask(~_inside_body(b, segs, np.stack([cx, cy], 1)))
    else:
        tri = Triangulation(xy[:, 0], xy[:, 1], m.triangles())
    lo = 0.0 if component == "von_mises_inplane" else values.min()
    hi = vmax if vmax is not None else values.max()
    pc = ax.tripcolor(tri, values, shading="gouraud", cmap=cmap, vmin=lo, vmax=hi)
    unit = _stress_unit(run)
    name = "in-plane von Mises stress" if component == "von_mises_inplane" else component
    fig.colorbar(pc, ax=ax, label=f"host: {name}" + (f" [{unit}]" if unit else ""), shrink=0.85)
    if grains:
        force_chains(run, ax=ax, title="", outline=False)
    ax.add_collection(LineCollection(segs, colors="0.3", linewidths=0.6))
    ax.set_aspect("equal")
    ax.autoscale_view()
    length = _units(run)[0]
    if length:
        ax.set_xlabel(f"x [{length}]")
        ax.set_ylabel(f"y [{length}]")
    ax.set_title(title or f"host {name} at the end, with the grains' force chains", fontsize=10)
    return _done(fig, path)
