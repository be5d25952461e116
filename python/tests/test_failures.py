#!/usr/bin/python3
"""Runs that do not end well, as a study meets them: not converged, killed, resumed, refused.

The three discs of case 1: with 20 iterations a step and no cut-back the first step cannot
converge (ConvergenceError, exit 3, gembem's message naming the step; the run directory says so
and holds step 0). Killed at its 60th output write (gembem's test hook GB_TEST_KILL_AT, as
ctest cli_resume does), the run raises GembemError naming the signal, its run_info.yaml says
`running` and, no process holding its lock, Run.status `killed`; gembem.resume completes it, and its steps.csv equals an uninterrupted run's (the wall
time aside). A second run of another scene into the same directory is refused before the first
run's scene file is overwritten.
"""
import os
import unittest

import numpy as np

import gembem
from common import RunDirTest

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


def case1():
    s = gembem.Scene.load(os.path.join(ROOT, "validation", "three_discs", "case1.yaml"))
    s.output = {"measures_every": 0}
    return s


class Failures(RunDirTest):
    def test_not_converged(self):
        s = case1().with_value("solver.max_iterations", 20).with_value("solver.cutbacks", 0)
        with self.assertRaises(gembem.ConvergenceError) as e:
            gembem.run(s, f"{self.tmp}/nc", quiet=True)
        self.assertEqual(e.exception.returncode, 3)
        self.assertIn("step 1", e.exception.message)
        self.assertIn("did not converge", e.exception.message)
        run = gembem.Run(f"{self.tmp}/nc")
        self.assertEqual(run.status, "not converged")
        self.assertEqual(list(run.steps["step"]), [0])

    def test_killed_and_resumed(self):
        whole = gembem.run(case1(), f"{self.tmp}/whole", quiet=True)
        with self.assertRaises(gembem.GembemError) as e:
            gembem.run(case1(), f"{self.tmp}/killed", quiet=True, env={"GB_TEST_KILL_AT": "60"})
        self.assertLess(e.exception.returncode, 0)
        self.assertIn("SIGKILL", e.exception.message)
        self.assertEqual(gembem.Run(f"{self.tmp}/killed").status, "killed")   # run_info.yaml: running, no holder
        seen = []
        run = gembem.resume(f"{self.tmp}/killed", progress=seen.append)
        self.assertEqual(run.status, "completed")
        self.assertGreater(seen[0].step, 1)                  # resumed, not started again
        self.assertEqual(seen[-1].step, 110)
        for name in run.steps:
            if name != "seconds":
                np.testing.assert_array_equal(run.steps[name], whole.steps[name], err_msg=name)

    def test_scene_file_kept(self):
        gembem.run(case1(), f"{self.tmp}/a", quiet=True)
        with open(f"{self.tmp}/a.yaml") as f:
            before = f.read()
        with self.assertRaisesRegex(FileExistsError, "a.yaml: the scene of an earlier run"):
            gembem.run(case1().with_value("solver.accuracy", 10), f"{self.tmp}/a", quiet=True)
        with open(f"{self.tmp}/a.yaml") as f:
            self.assertEqual(f.read(), before)
        run = gembem.run(case1().with_value("solver.accuracy", 10), f"{self.tmp}/a", quiet=True, overwrite=True)
        self.assertEqual(run.scene["solver"]["accuracy"], 10)


if __name__ == "__main__":
    unittest.main()
