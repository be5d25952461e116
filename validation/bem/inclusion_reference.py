#!/usr/bin/python3
"""The elliptic inclusion's reference (bem_inclusion --reference, Eshelby's equivalent inclusion)
against an independent solution by Kolosov-Muskhelishvili complex potentials (Hardiman 1954's
method, solved numerically).

The ellipse is the image of the unit circle by z = w(t) = e^(i angle) R (t + m / t), R = (a + b) / 2,
m = (a - b) / (a + b). Inside, uniform stress: phi = al z + c0, psi = be z + e0. Outside:
phi = A z + sum c_n t^-n, psi = B z + sum d_n t^-n, with A = (sxx + syy) / 4, B = (syy - sxx + 2i sxy) / 2
at infinity. On |t| = 1 the displacement 2 G u = k phi - z conj(phi') - conj(psi) and the force
function phi + z conj(phi') + conj(psi) are continuous (k = 3 - 4 nu in plane strain, (3 - nu) / (1 + nu)
in plane stress); the series is truncated at 60 terms and the coefficients fitted by least squares at
256 points, whose residual is reported (it would not vanish if the inside stress were not uniform).
Inside: sxx + syy = 4 Re al, syy - sxx + 2i sxy = 2 be.

Usage: inclusion_reference.py BEM_INCLUSION      (the path of the bem_inclusion program; exit 1 on a
       difference above 1e-9 of the reference's norm)"""
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import gembem  # noqa: E402


def inclusion_stress(mu, nu, mu_i, nu_i, plane_stress, a, b, angle, s, terms=60, points=256):
    kap = (3 - nu) / (1 + nu) if plane_stress else 3 - 4 * nu
    kap_i = (3 - nu_i) / (1 + nu_i) if plane_stress else 3 - 4 * nu_i
    R, m, rot = (a + b) / 2, (a - b) / (a + b), np.exp(1j * angle)
    A, B = (s[0] + s[1]) / 4, (s[1] - s[0] + 2j * s[2]) / 2
    t = np.exp(2j * np.pi * np.arange(points) / points)
    z, dz = rot * R * (t + m / t), rot * R * (1 - m / t**2)
    n = np.arange(1, terms + 1)[:, None]
    tn, dtn = t ** (-n), -n * t ** (-n - 1) / dz  # t^-n and its z-derivative, per term

    def jumps(x):
        """displacement and force-function jumps (inside - outside) for the coefficients x"""
        c = x[0::2] + 1j * x[1::2]
        al, be, c0, e0, cn, dn = c[0], c[1], c[2], c[3], c[4:4 + terms], c[4 + terms:]
        phi_i, dphi_i, psi_i = al * z + c0, al + 0 * z, be * z + e0
        phi_o, dphi_o, psi_o = A * z + cn @ tn, A + cn @ dtn, B * z + dn @ tn
        u_i = (kap_i * phi_i - z * np.conj(dphi_i) - np.conj(psi_i)) / (2 * mu_i)
        u_o = (kap * phi_o - z * np.conj(dphi_o) - np.conj(psi_o)) / (2 * mu)
        f_i = phi_i + z * np.conj(dphi_i) + np.conj(psi_i)
        f_o = phi_o + z * np.conj(dphi_o) + np.conj(psi_o)
        j = np.concatenate([u_i - u_o, f_i - f_o])
        return np.concatenate([j.real, j.imag])

    nx = 2 * (4 + 2 * terms)
    r0 = jumps(np.zeros(nx))
    M = np.array([jumps(e) - r0 for e in np.eye(nx)]).T  # the jumps are affine in x
    x = np.linalg.lstsq(M, -r0, rcond=None)[0]
    residual = np.abs(M @ x + r0).max()
    al, be = x[0] + 1j * x[1], x[2] + 1j * x[3]
    ssum, sdif = 4 * al.real, 2 * be
    return np.array([(ssum - sdif.real) / 2, (ssum + sdif.real) / 2, sdif.imag / 2]), residual


def main():
    out = subprocess.run([sys.argv[1], "--reference"], check=True, capture_output=True, text=True).stdout
    worst, worst_res, t = 0.0, 0.0, gembem.parse_csv(out, "bem_inclusion --reference")
    for i in range(t.nrows):
        f = {k: float(v[i]) for k, v in t.items()}
        s = (f["sxx"], f["syy"], f["sxy"])
        got = np.array([f["in_sxx"], f["in_syy"], f["in_sxy"]])
        want, res = inclusion_stress(f["mu"], f["nu"], f["mu_i"], f["nu_i"], int(f["plane_stress"]), f["a"], f["b"],
                                     f["angle"], s)
        norm = lambda v: np.sqrt(v[0]**2 + v[1]**2 + 2 * v[2]**2)
        worst, worst_res = max(worst, norm(got - want) / norm(want)), max(worst_res, res)
    print(f"{t.nrows} cases: max relative difference (Frobenius) Eshelby - complex potentials {worst:.1e}, "
          f"largest residual of the interface conditions {worst_res:.1e}")
    return 0 if t.nrows >= 54 and worst < 1e-9 and worst_res < 1e-9 else 1


if __name__ == "__main__":
    sys.exit(main())
