#!/usr/bin/python3
"""A thick cylinder (annulus a < r < b, plane strain, outer wall free) under an inner pressure p
at large displacements, in one dimension: the reference of gembem's updated-Lagrangian body
(ctest bem_updated_lagrangian, `updated_lagrangian` in a `gembem bem` scene).

1. Incremental linear elasticity on the current geometry (the model gembem's body solves): each
   pressure increment dp by Lame's formulas on the current radii a, b,
       du(r) = A r + B / r,  A = dp a^2 / (2 (lam + mu) (b^2 - a^2)),  B = dp a^2 b^2 / (2 mu (b^2 - a^2)),
   every material point moved by du. With n equal increments this is forward Euler on
   dr/dp = A' r + B' / r; the table shows the walls' displacements as n grows and the limit
   (the ODE solved by scipy's solve_ivp to rtol 1e-12), so that the answer is seen to stop changing.
2. For the record, a compressible neo-Hookean solid with the same small-strain moduli,
   W = mu / 2 (I1 - 3) - mu ln J + lam / 2 (ln J)^2 (plane strain), its pressure a follower
   (Cauchy traction -p on the current inner wall): the radial equilibrium
   dP_r/dR + (P_r - P_t) / R = 0 of the first Piola stresses, shot from R = a (where P_r = -p r/R)
   to R = b (where P_r = 0) with solve_ivp and brentq on the inner wall's place.

Usage: thick_cylinder_large.py [--mu 1] [--nu 0.3] [--a 1] [--b 2] [--p 0.05 0.1 0.2]
       [--check]   (exit 1 unless both models approach Lame's linear answer at small pressure,
                    the Euler sequence converges to the ODE's limit, and the shooting's residual is small)
"""
import argparse
import math
import sys

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq


def lame_rates(a, b, mu, lam):
    """A' and B' of du = (A' r + B' / r) dp on the current radii a, b."""
    d = b * b - a * a
    return a * a / (2 * (lam + mu) * d), a * a * b * b / (2 * mu * d)


def incremental_euler(p, n, a, b, mu, lam):
    """The walls' displacements after n equal increments."""
    ra, rb, dp = a, b, p / n
    for _ in range(n):
        A, B = lame_rates(ra, rb, mu, lam)
        ra, rb = ra + dp * (A * ra + B / ra), rb + dp * (A * rb + B / rb)
    return ra - a, rb - b


def incremental_limit(p, a, b, mu, lam):
    """The limit of infinitely many increments: the ODE in the pressure."""
    def rate(_, y):
        A, B = lame_rates(y[0], y[1], mu, lam)
        return [A * y[0] + B / y[0], A * y[1] + B / y[1]]
    s = solve_ivp(rate, (0, p), [a, b], method="DOP853", rtol=1e-12, atol=1e-14)
    return s.y[0, -1] - a, s.y[1, -1] - b


def piola(lr, lt, mu, lam):
    """First Piola stresses (radial, hoop) and dP_r/dl_r, dP_r/dl_t of the neo-Hookean solid."""
    lnj = math.log(lr * lt)
    pr = mu * lr - mu / lr + lam * lnj / lr
    pt = mu * lt - mu / lt + lam * lnj / lt
    return pr, pt, mu + mu / lr**2 + lam * (1 - lnj) / lr**2, lam / (lr * lt)


def neo_hookean(p, a, b, mu, lam):
    """The walls' displacements and the shooting's residual |P_r(b)| / p."""
    def rhs(R, y):
        r, dr = y
        lt = r / R
        pr, pt, dpr_dlr, dpr_dlt = piola(dr, lt, mu, lam)
        return [dr, (-(pr - pt) / R - dpr_dlt * (dr - lt) / R) / dpr_dlr]

    def outer_residual(ra):
        lt = ra / a
        lr = brentq(lambda x: piola(x, lt, mu, lam)[0] + p * lt, 0.05, 20)  # P_r(a) = -p r / R
        s = solve_ivp(rhs, (a, b), [ra, lr], method="DOP853", rtol=1e-12, atol=1e-14)
        return piola(s.y[1, -1], s.y[0, -1] / b, mu, lam)[0], s.y[0, -1]

    lin = incremental_euler(p, 1, a, b, mu, lam)[0]
    ra = brentq(lambda x: outer_residual(x)[0], a + 0.2 * lin, a + 5 * lin, xtol=1e-15, rtol=1e-15)
    res, rb = outer_residual(ra)
    return ra - a, rb - b, abs(res) / p


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--mu", type=float, default=1.0)
    ap.add_argument("--nu", type=float, default=0.3)
    ap.add_argument("--a", type=float, default=1.0)
    ap.add_argument("--b", type=float, default=2.0)
    ap.add_argument("--p", type=float, nargs="+", default=[0.05, 0.1, 0.2])
    ap.add_argument("--check", action="store_true")
    o = ap.parse_args()
    mu, a, b = o.mu, o.a, o.b
    lam = 2 * mu * o.nu / (1 - 2 * o.nu)
    bad = []
    print(f"thick cylinder {a} < r < {b}, plane strain, mu {mu}, nu {o.nu}, outer wall free")
    for p in o.p:
        lin = incremental_euler(p, 1, a, b, mu, lam)
        lim = incremental_limit(p, a, b, mu, lam)
        print(f"\np = {p:g}: linear (one increment) u_a {lin[0]:.8f}, u_b {lin[1]:.8f} "
              f"(hoop strain at the inner wall {lin[0] / a:.4f})")
        print("  incremental linear, n increments:   u_a          u_b          u_a / limit - 1")
        prev = None
        for n in (10, 20, 40, 80, 160, 320, 640, 1280, 10240):
            ua, ub = incremental_euler(p, n, a, b, mu, lam)
            print(f"  {n:6d} {ua:22.10f} {ub:12.10f} {ua / lim[0] - 1:+.3e}")
            prev = (n, ua)
        print(f"  limit  {lim[0]:22.10f} {lim[1]:12.10f}   (hoop strain {lim[0] / a:.4f})")
        nh = neo_hookean(p, a, b, mu, lam)
        print(f"  neo-Hookean:  u_a {nh[0]:.10f}, u_b {nh[1]:.10f} (hoop strain {nh[0] / a:.4f}; shooting "
              f"residual {nh[2]:.1e}); incremental linear / neo-Hookean - 1: u_a {lim[0] / nh[0] - 1:+.3e}, "
              f"u_b {lim[1] / nh[1] - 1:+.3e}")
        if abs(prev[1] / lim[0] - 1) > 1e-4:
            bad.append(f"p {p}: {prev[0]} increments are {prev[1] / lim[0] - 1:.2e} from the limit")
        if nh[2] > 1e-8:
            bad.append(f"p {p}: shooting residual {nh[2]:.1e}")
    # at a small pressure both large-displacement models are Lame's linear solution
    ps = 1e-7
    lin, lim, nh = incremental_euler(ps, 1, a, b, mu, lam), incremental_limit(ps, a, b, mu, lam), \
        neo_hookean(ps, a, b, mu, lam)
    dev = max(abs(lim[0] / lin[0] - 1), abs(nh[0] / lin[0] - 1), abs(nh[1] / lin[1] - 1))
    print(f"\np = {ps:g}: both models / linear - 1 at most {dev:.1e} (the geometry's change, about the strain)")
    if dev > 1e-6:
        bad.append(f"p {ps}: the models differ from Lame's linear answer by {dev:.1e}")
    if o.check and bad:
        print("\n".join(bad), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
