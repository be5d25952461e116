#!/usr/bin/python3
"""Checks a `gembem pack` directory without gembem's code: every grain inside its region (a box, or
the cavity polygon read from the gmsh .msh file itself, point-in-polygon by ray casting and the
distance to its edges), no overlap between grains or with a wall or the polygon beyond a share of
the (smaller) radius, the solid fraction from the
written grains and the region's area (shoelace), the force and moment balance of every grain from
the written contact forces, and that pack_info.yaml reports these numbers.

  check_pack.py DIR (--box L R B T | --msh FILE --group NAME) --max-overlap F --accuracy A
                [--weight W] [--solid-fraction PHI --tolerance T] [--stress S --stress-tolerance T]
"""
import argparse
import csv
import math
import sys


def read_msh2_loop(path, group):
    """The cavity's edges (2-node lines of the physical group) from an ASCII MSH 2.2 file."""
    lines = open(path).read().split("\n")
    k = lines.index("$PhysicalNames")
    tag = None
    for row in lines[k + 2:k + 2 + int(lines[k + 1])]:
        dim, t, name = row.split(maxsplit=2)
        if dim == "1" and name.strip('"') == group:
            tag = int(t)
    k = lines.index("$Nodes")
    nodes = {}
    for row in lines[k + 2:k + 2 + int(lines[k + 1])]:
        v = row.split()
        nodes[int(v[0])] = (float(v[1]), float(v[2]))
    k = lines.index("$Elements")
    edges = []
    for row in lines[k + 2:k + 2 + int(lines[k + 1])]:
        v = [int(x) for x in row.split()]
        if v[1] == 1 and v[3] == tag:  # type 1: a 2-node line; its first tag the physical group
            edges.append((nodes[v[-2]], nodes[v[-1]]))
    return edges


def shoelace(edges):
    # chained into one loop, so that the orientation is consistent whatever the lines' own
    nxt = {}
    for a, b in edges:
        nxt.setdefault(a, []).append(b)
        nxt.setdefault(b, []).append(a)
    start = edges[0][0]
    loop, prev, cur = [start], None, start
    while True:
        cand = [p for p in nxt[cur] if p != prev]
        prev, cur = cur, cand[0]
        if cur == start:
            break
        loop.append(cur)
    assert len(loop) == len(edges), "the cavity is not one closed loop"
    s = sum(loop[i][0] * loop[(i + 1) % len(loop)][1] - loop[(i + 1) % len(loop)][0] * loop[i][1]
            for i in range(len(loop)))
    return abs(s) / 2


def inside(edges, x, y):
    c = False
    for (x0, y0), (x1, y1) in edges:
        if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
            c = not c
    return c


def distance(edges, x, y):
    best = math.inf
    for (x0, y0), (x1, y1) in edges:
        dx, dy = x1 - x0, y1 - y0
        s = max(0.0, min(1.0, ((x - x0) * dx + (y - y0) * dy) / (dx * dx + dy * dy)))
        best = min(best, math.hypot(x - x0 - s * dx, y - y0 - s * dy))
    return best


def info(path):
    out = {}
    for line in open(path):
        if line.startswith("#") or ":" not in line:
            continue
        key, val = line.split(":", 1)
        out[key.strip()] = val.split("#")[0].strip()
    return out


def main():
    p = argparse.ArgumentParser()
    p.add_argument("dir")
    p.add_argument("--box", type=float, nargs=4)
    p.add_argument("--msh")
    p.add_argument("--group", default="cavity")
    p.add_argument("--max-overlap", type=float, required=True)
    p.add_argument("--accuracy", type=float, required=True)
    p.add_argument("--weight", type=float, default=0.0)
    p.add_argument("--solid-fraction", type=float)
    p.add_argument("--tolerance", type=float, default=1e-9)
    p.add_argument("--friction-deg", type=float, help="packed with this friction: every contact inside its cone, "
                   "and most contacts carrying a tangential force")
    p.add_argument("--stress", type=float, help="in a box: the target mean stress, against Love's from the "
                   "written contacts")
    p.add_argument("--stress-tolerance", type=float, default=0.01, help="relative, for --stress")
    p.add_argument("--eta", type=float, help="with --friction-deg: the grains' rolling limit, every rolling moment "
                   "within it")
    a = p.parse_args()
    fails = []
    g = [(float(r["x"]), float(r["y"]), float(r["r"])) for r in csv.DictReader(open(a.dir + "/state_grains.csv"))]
    inf = info(a.dir + "/pack_info.yaml")
    if a.box:
        L, R, B, T = a.box
        area = (R - L) * (T - B)
        for i, (x, y, r) in enumerate(g):
            if min(x - L, R - x, y - B, T - y) < r * (1 - a.max_overlap):
                fails.append(f"grain {i} crosses a wall by more than {a.max_overlap} of its radius")
    else:
        edges = read_msh2_loop(a.msh, a.group)
        area = shoelace(edges)
        for i, (x, y, r) in enumerate(g):
            if not inside(edges, x, y):
                fails.append(f"grain {i} ({x}, {y}) has its centre outside the cavity")
            elif distance(edges, x, y) < r * (1 - a.max_overlap):
                fails.append(f"grain {i} crosses the cavity's boundary: distance {distance(edges, x, y)}, radius {r}")
    worst = 0.0
    for i in range(len(g)):
        for j in range(i + 1, len(g)):
            (xi, yi, ri), (xj, yj, rj) = g[i], g[j]
            worst = max(worst, (ri + rj - math.hypot(xj - xi, yj - yi)) / min(ri, rj))
    if worst > a.max_overlap:
        fails.append(f"two grains overlap by {worst:.4g} of the smaller radius, more than {a.max_overlap}")
    phi = sum(math.pi * r * r for _, _, r in g) / area
    if abs(phi - float(inf["solid_fraction"])) > 1e-9 * phi:
        fails.append(f"solid fraction {phi} from the grains and the region, {inf['solid_fraction']} reported")
    if abs(area - float(inf["region"].split("area:")[1].rstrip("}"))) > 1e-9 * area:
        fails.append(f"area {area} of the region, {inf['region']} reported")
    if a.solid_fraction is not None and abs(phi - a.solid_fraction) > a.tolerance:
        fails.append(f"solid fraction {phi}, target {a.solid_fraction} +- {a.tolerance}")
    if int(inf["grains"]) != len(g):
        fails.append(f"{len(g)} grains written, {inf['grains']} reported")
    # balance (K 5): a contact pushes grain i by -(pn n + pt t), n the unit normal from i to j and
    # t = (-ny, nx), and j by the opposite; its tangential force turns both by pt times their radius
    # (in force units: pt), and a rolling moment mr turns i by -mr and j by +mr (over their radius,
    # in the same units). Plus the weight. An earlier version of this check added +pt t to i: right
    # only while every pt was 0 (the frictionless settling), 260 dyn off once friction acted.
    # Love's mean stress, (1/2A) sum of f . l over the contacts, l from a grain's centre to the other's
    # (pn |l|: the tangential force is normal to l) or to the wall (the centre's distance to it)
    F = [[0.0, -a.weight * math.pi * r * r, 0.0] for _, _, r in g]
    gg = bd = 0
    virial = 0.0
    for c in csv.DictReader(open(a.dir + "/state_contacts.csv")):
        i, pn, pt, nx, ny = int(c["i"]), float(c["pn"]), float(c["pt"]), float(c["nx"]), float(c["ny"])
        xi, yi = g[i][0], g[i][1]
        if c["j"].isdigit():
            virial += pn * math.hypot(g[int(c["j"])][0] - xi, g[int(c["j"])][1] - yi)
        elif a.box:
            virial += pn * {"left": xi - L, "right": R - xi, "bottom": yi - B, "top": T - yi}[c["j"]]
        mr = float(c.get("mr") or 0)  # rolling resistance: mr on i, -mr on j (a moment: over the radius)
        fx, fy = -(pn * nx + pt * -ny), -(pn * ny + pt * nx)
        F[i][0] += fx
        F[i][1] += fy
        F[i][2] += pt - mr / g[i][2]
        if c["j"].isdigit():
            j = int(c["j"])
            F[j][0] -= fx
            F[j][1] -= fy
            F[j][2] += pt + mr / g[j][2]
            gg += 1
        else:
            bd += 1
    if a.friction_deg is not None:
        # Coulomb (K 13) at the packing's angle; a packing made frictionless has no tangential force
        # (the solver finds it in balance at once), so most contacts carrying one says friction acted
        mu, cones, carrying, n = math.tan(math.radians(a.friction_deg)), 0, 0, 0
        for c in csv.DictReader(open(a.dir + "/state_contacts.csv")):
            pn, pt = float(c["pn"]), float(c["pt"])
            n += 1
            cones += abs(pt) > mu * pn * (1 + 1e-9)
            if a.eta is not None and c["j"].isdigit():  # the rolling limit eta R* pn, R* = ri rj / (ri + rj)
                ri, rj = g[int(c["i"])][2], g[int(c["j"])][2]
                cones += abs(float(c["mr"])) > a.eta * ri * rj / (ri + rj) * pn * (1 + 1e-9)
            carrying += abs(pt) > 1e-3 * pn
        if cones:
            fails.append(f"{cones} contacts outside the Coulomb cone of {a.friction_deg} degrees (or the rolling limit)")
        if not carrying > n / 2:
            fails.append(f"only {carrying} of {n} contacts carry a tangential force above 1e-3 of their normal one")
        print(f"{a.dir}: {carrying} of {n} contacts carry a tangential force, {cones} outside the cone")
    fmax = max(math.sqrt(f[0] ** 2 + f[1] ** 2 + f[2] ** 2) for f in F)
    if fmax > a.accuracy:
        fails.append(f"a grain is out of balance by {fmax:.4g}, more than the accuracy {a.accuracy}")
    if inf["contacts"] != f"{{grain_grain: {gg}, boundary: {bd}}}":
        fails.append(f"contacts {gg} + {bd} written, {inf['contacts']} reported")
    if a.stress is not None:
        sigma = virial / (2 * area)
        print(f"{a.dir}: mean stress {sigma:.6g} from the contacts (Love), target {a.stress:g}")
        if not abs(sigma / a.stress - 1) <= a.stress_tolerance:
            fails.append(f"mean stress {sigma:.6g}, target {a.stress:g} +- {100 * a.stress_tolerance:g} %")
    z = (2 * gg + bd) / len(g)
    if abs(z - float(inf["coordination"])) > 1e-12:
        fails.append(f"coordination {z} from the contacts, {inf['coordination']} reported")
    print(f"{a.dir}: {len(g)} grains, solid fraction {phi:.6f} (area {area:.6f}), largest overlap {worst:.4g}, "
          f"coordination {z:.3f}, largest out-of-balance force {fmax:.3g} (accuracy {a.accuracy})")
    for f in fails:
        print("FAIL", f)
    sys.exit(1 if fails else 0)


main()
