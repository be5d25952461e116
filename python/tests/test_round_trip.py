#!/usr/bin/python3
"""A scene written from Python is the scene gembem reads: numbers exact, errors raised with gembem's message.

60 grains of random radii on a loose grid (no contact, so nothing moves), written inline and as
a CSV file: gembem's state after one relaxation step holds the very doubles Python wrote, the box
is steps.csv's width and height, and the run's copy of the scene loads back to the same objects.
A bad value comes back as SceneError (exit 2) naming the file, line and column, with no run
directory; a GEMBEM that is not an executable is an error, not a fallback.
"""
import os
import unittest

import numpy as np

import gembem
from common import RunDirTest


def grains(n=60, seed=7):
    rng = np.random.default_rng(seed)
    i = np.arange(n)
    xy = np.stack([1.5 + 3.0 * (i % 10), 1.5 + 3.0 * (i // 10)], 1) + rng.uniform(-0.3, 0.3, (n, 2))
    r = rng.uniform(0.4, 1.0, n) * (1 + 1e-13 * rng.standard_normal(n))   # digits down to the last
    return np.column_stack([xy, r, rng.uniform(-1, 1, n)])


def scene(g):
    return gembem.Scene(
        units={"length": "cm", "force": "dyn"},
        materials={"grain_grain": {"kn": 1e8, "kt": 7e7, "friction_deg": 25.0},
                   "grain_wall": {"kn": 1e8, "kt": 7e7, "friction_deg": np.float64(0)}},
        grains=g, box={"left": 0.0, "right": 30.0, "bottom": 0.0, "top": 18.0 + 1e-9},
        solver={"accuracy": 1.0, "max_iterations": 100},
        loading=[{"relax": {"steps": 1}}], output={"measures_every": 0})


class RoundTrip(RunDirTest):
    def check(self, name, grains_file):
        g = grains()
        sc = scene(g)
        run = gembem.run(sc, f"{self.tmp}/{name}", grains_file=grains_file, quiet=True)
        self.assertEqual(run.status, "completed")
        st = run.state
        for k, col in enumerate(("x", "y", "r", "rotation")):
            np.testing.assert_array_equal(st.grains[col], g[:, k], err_msg=f"{name}: column {col}")
        self.assertEqual(st.contacts.nrows, 0)
        self.assertEqual(run.steps["width"][0], 30.0)
        self.assertEqual(run.steps["height"][0], 18.0 + 1e-9)
        # gembem's copy of the scene (scene.yaml) loads back to what Python wrote.
        back = gembem.Scene.load(run.file("scene.yaml")).to_dict()
        sent = sc.to_dict(grains_file)
        if grains_file:
            self.assertTrue(os.path.isabs(back["grains"]["file"]))   # made absolute by Scene.load
            back["grains"]["file"] = sent["grains"]["file"]
        self.assertEqual(back, sent)

    def test_inline(self):
        self.check("inline", None)

    def test_grains_csv(self):
        self.check("csv", "grains.csv")
        self.assertTrue(os.path.isfile(f"{self.tmp}/grains.csv"))

    def test_numbers_as_gembem_reads_them(self):
        # YAML 1.2 floats that PyYAML alone reads as strings: 1.0e8 (unsigned exponent), 1.5e5
        sc = gembem.Scene.load(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                            "validation", "three_discs", "case1.yaml"))
        self.assertEqual(sc.materials["grain_grain"]["kn"], 1.0e8)
        self.assertEqual(sc.loading[0]["isotropic"]["stress"], 1.5e5)
        self.assertIn("kn: 100000000.0", sc.to_yaml())

    def test_with_value(self):
        sc = scene(grains())
        sc2 = sc.with_value("materials.grain_grain.friction_deg", 30).with_value("loading.0.relax.steps", 2)
        self.assertEqual(sc.materials["grain_grain"]["friction_deg"], 25.0)   # the original untouched
        self.assertEqual(sc2.to_dict()["materials"]["grain_grain"]["friction_deg"], 30)
        self.assertEqual(sc2.loading[0]["relax"]["steps"], 2)

    def test_scene_error(self):
        bad = scene(grains()).with_value("materials.grain_wall.kn", -5.0)
        with self.assertRaises(gembem.SceneError) as e:
            gembem.run(bad, f"{self.tmp}/bad", quiet=True)
        self.assertEqual(e.exception.returncode, 2)
        self.assertRegex(e.exception.message, r"bad\.yaml:\d+:\d+: materials\.grain_wall\.kn")
        self.assertFalse(os.path.exists(f"{self.tmp}/bad"))
        with self.assertRaises(gembem.SceneError) as e:      # an existing run directory
            gembem.run(scene(grains()), f"{self.tmp}/ok", quiet=True)
            gembem.run(scene(grains()), f"{self.tmp}/ok", quiet=True)
        self.assertIn("ok", e.exception.message)

    def test_bad_executable(self):
        with self.assertRaises(FileNotFoundError) as e:
            gembem.find_gembem(os.path.join(self.tmp, "no_gembem"))
        self.assertIn("no_gembem", str(e.exception))


if __name__ == "__main__":
    unittest.main()
