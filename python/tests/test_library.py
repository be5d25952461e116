#!/usr/bin/python3
"""The library in this process (gembem.Simulation, ctypes) against the `gembem run` command.

The three discs of case 1 (10 isotropic steps, then 100 of shear, counted in the scene file) and
the 27-grain cavity packing of tests/cli/scenes/step_error_host.yaml (a hybrid scene: relax,
then two host_load stages of 2 steps), each taken one step at a time in this process, from the
scene file and from a gembem.Scene (YAML text in memory): the state files that the library's own
writer puts down equal those of `gembem run` byte for byte, and every step's report equals its
row of the command's steps.csv. Between steps: the grains at step 0 are the scene's, the walls
are the box, s1 = (F_bottom + F_top) / 2 width (K section 4.1), a sliding contact has |pt| =
pn tan(phi) (phi from the scene; none without friction), the host's fixing forces are within the accuracy and its left
side carries the pressure given (10 a step, 2 steps) times its length (10, meshes/
square_cavity_sides.geo). A bad scene raises SceneError at its line and column; a step that does
not converge raises ConvergenceError and leaves the last completed step's state.
"""
import math
import os
import subprocess
import unittest

import numpy as np

import gembem
from common import RunDirTest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
CASE1 = os.path.join(ROOT, "validation", "three_discs", "case1.yaml")
HOST = os.path.join(ROOT, "tests", "cli", "scenes", "step_error_host.yaml")
STATE_FILES = ("state.yaml", "state_grains.csv", "state_contacts.csv")


class Library(RunDirTest):
    def command_run(self, scene):
        """`gembem run SCENE -o run` in self.tmp, moved to cli/: the in-process state is then
        written to run/, so that state.yaml's line naming its own path is the same."""
        subprocess.run([gembem.find_gembem(), "run", scene, "-o", "run", "--quiet"], cwd=self.tmp, check=True)
        os.rename(f"{self.tmp}/run", f"{self.tmp}/cli")
        return gembem.Run(f"{self.tmp}/cli")

    def assert_same_state(self, sim, files):
        cwd = os.getcwd()
        os.chdir(self.tmp)
        try:
            sim.write_state("run")
        finally:
            os.chdir(cwd)
        for f in files:
            with open(f"{self.tmp}/cli/{f}", "rb") as a, open(f"{self.tmp}/run/{f}", "rb") as b:
                self.assertEqual(a.read(), b.read(), f)

    def assert_reports(self, reports, steps):
        self.assertEqual([r.step for r in reports], list(steps["step"]))
        self.assertEqual([r.iterations for r in reports], list(steps["iterations"]))
        self.assertEqual([r.n_contacts for r in reports], list(steps["contacts"]))
        for name in ("s1", "s2", "stress_ratio", "e1", "e2"):
            got = np.array([getattr(r, name) for r in reports])
            np.testing.assert_allclose(got, steps[name].astype(float), rtol=1e-9, atol=0, equal_nan=True,
                                       err_msg=name)

    def test_three_discs_by_steps_equal_the_command(self):
        cli = self.command_run(CASE1)
        scene = gembem.Scene.load(CASE1)
        with gembem.Simulation(CASE1) as sim:
            self.assertEqual(sim.place["step"], -1)
            r0 = sim.step()
            self.assertEqual((r0.step, r0.stage), (0, -1))
            g = sim.grains
            np.testing.assert_array_equal(np.c_[g["x"], g["y"], g["r"]], np.array(scene.grains["list"]))
            np.testing.assert_array_equal(g["rotation"], 0)
            w = sim.walls
            self.assertEqual(list(w["wall"]), ["left", "right", "bottom", "top"])
            self.assertEqual(list(w["position"]), [scene.box[k] for k in ("left", "right", "bottom", "top")])
            reports = [r0] + sim.run_stage()  # the isotropic stage: 10 steps
            self.assertEqual(len(reports), 1 + scene.loading[0]["isotropic"]["steps"])
            self.assertEqual(sim.place, {"step": 10, "stage": 0, "stage_step": 10, "stage_steps": 10,
                                         "total_steps": 110, "n_stages": 2})
            w, r = sim.walls, reports[-1]
            width = w["position"][1] - w["position"][0]
            self.assertAlmostEqual((w["force"][2] + w["force"][3]) / (2 * width), r.s1, delta=1e-9 * r.s1)
            self.assertAlmostEqual(r.s1, 1.5e5, delta=r.accuracy / width)  # the target, to the walls' accuracy
            while not sim.finished:
                reports.append(sim.step())
                c = sim.contacts
                self.assertTrue(np.all(c["i"] < np.where(c["j"] >= 0, c["j"], np.inf)))
                self.assertFalse(c["sliding"].any())  # frictionless (friction_deg: 0): no shear to slide
            self.assertEqual(len(reports), 111)
            self.assert_reports(reports, cli.steps)
            steps = sim.steps  # by steps.csv's names
            for name in ("step", "stage", "iterations", "contacts", "substeps", "rattlers"):
                np.testing.assert_array_equal(steps[name], cli.steps[name], err_msg=name)
            for name in ("e1_minus_e2", "s1", "stress_ratio", "force_scale"):
                np.testing.assert_allclose(steps[name], cli.steps[name].astype(float), rtol=1e-9, atol=1e-300,
                                           err_msg=name)
            np.testing.assert_allclose(steps["coordination"], cli.steps["coordination"], atol=5e-7)  # written %f
            self.assert_same_state(sim, STATE_FILES)
            with self.assertRaises(gembem.SceneError) as e:
                sim.step()
            self.assertIn("finished", e.exception.message)

    def test_scene_object_equals_the_file(self):
        self.command_run(CASE1)
        scene = gembem.Scene.load(CASE1)
        with gembem.Simulation(scene, name=os.path.join(self.tmp, "built.yaml")) as sim:
            sim.run()
            self.assert_same_state(sim, STATE_FILES)

    def test_hybrid_equals_the_command(self):
        cli = self.command_run(HOST)
        with gembem.Simulation(HOST) as sim:
            reports = sim.run_stage()  # step 0 and the relax stage
            self.assertEqual([r.step for r in reports], [0, 1])
            slid = 0
            while not sim.finished:
                reports.append(sim.step())
                c = sim.contacts
                between = c["j"] >= 0  # friction_deg: 25; against boundary particles kt = 0: no shear
                expect = np.abs(c["pt"]) >= c["pn"] * math.tan(math.radians(25)) * (1 - 1e-9)
                np.testing.assert_array_equal(c["sliding"], between & expect)
                slid += c["sliding"].sum()
            self.assertGreater(slid, 0)
            h = sim.host
            self.assertEqual(h.nrows, 24)  # host.elements: cavity: 24
            self.assertLessEqual(np.max(np.hypot(h["fix_x"], h["fix_y"])), reports[-1].accuracy)
            force, disp = sim.host_group("left")
            self.assertAlmostEqual(force[0], 2 * 10 * 10, delta=1e-9 * 200)  # inward pressure 20 on a side 10
            self.assertAlmostEqual(force[1], 0, delta=1e-9 * 200)
            self.assertTrue(np.all(np.isnan(sim.walls["force"]) | (sim.walls["force"] == 0)))
            with self.assertRaises(gembem.SceneError):
                sim.host_group("no_such_group")
            self.assert_reports(reports, cli.steps)
            self.assert_same_state(sim, STATE_FILES + ("state_host.csv",))


class LibraryErrors(RunDirTest):
    def test_bad_scene_raises_at_its_line_and_column(self):
        path = f"{self.tmp}/bad.yaml"
        with open(CASE1) as f:
            lines = f.read().splitlines()
        # materials.grain_grain's kn misspelt; on line k, column 17 of "  grain_grain: {knn: ..."
        k = next(n for n, line in enumerate(lines, 1) if line.startswith("  grain_grain:"))
        lines[k - 1] = lines[k - 1].replace("{kn:", "{knn:")
        with open(path, "w") as f:
            f.write("\n".join(lines) + "\n")
        with self.assertRaises(gembem.SceneError) as e:
            gembem.Simulation(path)
        self.assertEqual((e.exception.file, e.exception.line, e.exception.column), (path, k, 17))
        self.assertIn("materials.grain_grain.kn", e.exception.message)
        self.assertEqual(e.exception.returncode, 2)
        # the same from a Scene object: the place in the text given to the library, under its name
        scene = gembem.Scene.load(CASE1).with_value("materials.grain_grain.kn", -1.0)
        text = scene.to_yaml().splitlines()
        k = next(n for n, line in enumerate(text, 1) if "kn: -1.0" in line)
        with self.assertRaises(gembem.SceneError) as e:
            gembem.Simulation(scene, name="built.yaml")
        self.assertEqual((e.exception.file, e.exception.line), ("built.yaml", k))
        self.assertEqual(e.exception.column, text[k - 1].index("-1.0") + 1)

    def test_failed_step_keeps_the_last_state(self):
        scene = gembem.Scene.load(CASE1).with_value("solver.cutbacks", 0)
        with gembem.Simulation(scene.with_value("solver.max_iterations", 20)) as sim:
            sim.step()
            before = sim.grains
            with self.assertRaises(gembem.ConvergenceError) as e:
                sim.step()
            self.assertIn("step 1", e.exception.message)
            self.assertEqual(sim.place["step"], 0)
            for k in before:
                np.testing.assert_array_equal(sim.grains[k], before[k])


if __name__ == "__main__":
    unittest.main()
