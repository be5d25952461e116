#!/usr/bin/python3
"""Kishino's three discs (1989, Table 1 case 4) built from Python objects, against the exact solution.

Two discs of radius 1 on the bottom wall, one resting on both (theta0 = 60 deg), frictionless,
kn = 1e10: isotropic compression to 1.5e5 dyn/cm, then shear at constant mean stress. The stress
ratio of the shear stage at e1 - e2 = 1..5 % (read from steps.csv) must be within 0.0003 of the
rigid exact solution (validation/three_discs/table2.py's exact_ratio, (K 19)-(K 21)), the bound
the C test validation_three_discs_case4 holds; the run's progress reaches the caller step by step. The same
in two runs, the shear starting from the preparation's final state (initial_state: a Run), gives
the same stress ratios (restarting is exact).
"""
import math
import os
import sys
import unittest

import numpy as np

import gembem
from common import RunDirTest

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(ROOT, "validation", "three_discs"))
from table2 import exact_ratio  # noqa: E402

SHEAR_STEPS = 100


def three_discs(kn, accuracy):
    r, h = 1.0, 2 * math.sin(math.radians(60))
    spring = {"kn": kn, "kt": 0.7 * kn, "friction_deg": 0}
    return gembem.Scene(
        units={"length": "cm", "force": "dyn"},
        materials={"grain_grain": spring, "grain_wall": dict(spring)},
        grains=[[r, r, r], [3 * r, r, r], [2 * r, r + h * r, r]],
        box={"left": 0.0, "right": 4 * r, "bottom": 0.0, "top": 2 * r * (1 + math.sin(math.radians(60)))},
        solver={"alpha": 0.75, "accuracy": accuracy, "max_iterations": 100000},
        loading=[{"isotropic": {"stress": 1.5e5, "steps": 10}},
                 {"shear_mean_stress": {"d_e1_minus_e2": 0.0005, "steps": SHEAR_STEPS, "mean_stress": 1.5e5,
                                        "reset_strain": True}}],
        output={"measures_every": 0})


class ThreeDiscs(RunDirTest):
    def test_case4_exact(self):
        seen = []
        run = gembem.run(three_discs(1e10, 1.0), f"{self.tmp}/case4", progress=seen.append, quiet=False)
        total = 10 + SHEAR_STEPS
        self.assertEqual([p.step for p in seen], list(range(total + 1)))
        self.assertEqual(seen[-1].total, total)
        s = run.steps
        self.assertAlmostEqual(seen[-1].stress_ratio, s["stress_ratio"][-1], delta=1e-4)   # %.4f on the line
        shear = s.select(s["stage"] == 2)
        self.assertEqual(shear.nrows, SHEAR_STEPS)
        for k in range(1, 6):
            at = np.nonzero(np.abs(shear["e1_minus_e2"] - 0.01 * k) < 1e-9)[0]
            self.assertEqual(len(at), 1, f"one shear step at e1 - e2 = {k} %")
            got, exact = shear["stress_ratio"][at[0]], exact_ratio(0.01 * k)
            self.assertLess(abs(got - exact), 3e-4, f"e1 - e2 = {k} %: {got} against the exact {exact}")
        np.testing.assert_allclose(shear["s1"] + shear["s2"], 3.0e5, rtol=1e-3)   # constant mean stress

        whole = three_discs(1e10, 1.0)
        prep = gembem.run(whole.with_value("loading", whole.loading[:1]), f"{self.tmp}/prep", quiet=True)
        then = gembem.Scene(units=whole.units, materials=whole.materials, initial_state=prep,
                            solver=whole.solver, loading=whole.loading[1:], output=whole.output)
        self.assertEqual(then.to_dict()["initial_state"], os.path.realpath(f"{self.tmp}/prep/state.yaml"))
        sheared = gembem.run(then, f"{self.tmp}/shear", quiet=True)
        np.testing.assert_allclose(sheared.steps["stress_ratio"][1:], shear["stress_ratio"], rtol=0, atol=1e-12)


if __name__ == "__main__":
    unittest.main()
