#!/usr/bin/python3
"""Two discs between two walls, squeezed sideways: the package's numbers against springs in series.

Left wall - disc A (r 1) - disc B (r 0.5) - right wall, touching with no force, no friction, no
body force; the width is cut by de2 W0 per step (strain control). The three contacts carry one
force P = delta / (2/kw + 1/kg), delta the width lost: the overlaps P/kw at the walls, P/kg
between the discs, the wall's stress s2 = P / height, the discs moved to where the overlaps put
them, each grain's contact forces summing to zero (its fixing force). The scene is built from
Python objects, run through gembem.run and read back with Run.
"""
import unittest

import numpy as np

import gembem
from common import RunDirTest

KG, KW = 1.0e8, 2.0e8          # grain-grain and grain-wall normal springs
R_A, R_B, H = 1.0, 0.5, 4.0
DE2, STEPS = 1.0e-3, 3


def scene():
    return gembem.Scene(
        units={"length": "cm", "force": "dyn"},
        materials={"grain_grain": {"kn": KG, "kt": 0, "friction_deg": 0},
                   "grain_wall": {"kn": KW, "kt": 0, "friction_deg": 0}},
        grains=np.array([[R_A, H / 2, R_A], [2 * R_A + R_B, H / 2, R_B]]),
        box={"left": 0.0, "right": 2 * (R_A + R_B), "bottom": 0.0, "top": H},
        solver={"accuracy": 1e-3, "max_iterations": 100000},
        loading=[{"strain": {"de1": 0, "de2": DE2, "steps": STEPS}}])


class TwoDiscs(RunDirTest):
    def test_springs_in_series(self):
        seen = []
        run = gembem.run(scene(), f"{self.tmp}/run", progress=seen.append)
        self.assertEqual([p.step for p in seen], list(range(STEPS + 1)), "a progress record per step")
        self.assertTrue(all(p.total == STEPS for p in seen))
        w0 = 2 * (R_A + R_B)
        s = run.steps
        self.assertEqual(list(s["step"]), list(range(STEPS + 1)))
        for k in range(STEPS + 1):
            delta = k * DE2 * w0
            p = delta / (2 / KW + 1 / KG)
            self.assertAlmostEqual(s["e2"][k], k * DE2, delta=1e-12)
            self.assertAlmostEqual(s["width"][k], w0 - delta, delta=1e-12)
            self.assertAlmostEqual(s["s2"][k] / (p / H if p else 1.0), 1.0 if p else 0.0, delta=1e-8)
            self.assertAlmostEqual(s["s1"][k], 0.0, delta=1e-9)

        delta = STEPS * DE2 * w0
        p = delta / (2 / KW + 1 / KG)
        st = run.state
        c = st.contacts
        self.assertEqual(sorted(c["j"]), ["1", "left", "right"])
        for j, k_n in (("left", KW), ("1", KG), ("right", KW)):
            row = c.select(c["j"] == j)
            self.assertAlmostEqual(row["pn"][0] / p, 1.0, delta=1e-8, msg=j)
            self.assertAlmostEqual(row["overlap"][0] / (p / k_n), 1.0, delta=1e-8, msg=j)
            self.assertEqual(row["pt"][0], 0.0)
        # Where the overlaps put the discs: A pressed into the left wall, B into the right one.
        left = st.box["left"]
        self.assertAlmostEqual(left, 0.5 * delta, delta=1e-12)   # both walls move by half
        self.assertAlmostEqual(st.grains["x"][0], left + R_A - p / KW, delta=1e-9)
        self.assertAlmostEqual(st.grains["x"][1], st.box["right"] - R_B + p / KW, delta=1e-9)
        np.testing.assert_allclose(st.grains["y"], H / 2, atol=1e-12)
        # Each grain's contact forces (pn along n from the grain to the other side) cancel.
        f = np.zeros((2, 2))
        for i, j, pn, nx, ny in zip(c["i"], c["j"], c["pn"], c["nx"], c["ny"]):
            f[i] += pn * np.array([nx, ny])
            if j.isdigit():
                f[int(j)] -= pn * np.array([nx, ny])
        self.assertLess(np.abs(f).max(), 2e-3)   # the scene's accuracy


if __name__ == "__main__":
    unittest.main()
