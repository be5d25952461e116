#!/usr/bin/python3
"""Package functions on hand-written inputs. gembem.table's one reader on CSV text: parse_csv (text a tool printed) and
read_csv (the same text in a file) give the same columns, each of the type its values need, with
the numbers written in the text; comments and blank lines are skipped; a short row is an error
naming its line. gembem.figures.iteration_forces on a hand-written run directory. A scene
written with a comment: the comment's lines first, the sections read back unchanged."""
import os
import unittest

import numpy as np

import gembem
from common import RunDirTest

TEXT = """# case,N,seconds,error written by a benchmark
case,N,seconds,error
lame,16,0.0125,3.5e-2

kirsch,32,2,-1e-05
"""


class Table(RunDirTest):
    def check(self, t):
        self.assertEqual(list(t), ["case", "N", "seconds", "error"])
        self.assertEqual(t.nrows, 2)
        self.assertEqual(t["case"].tolist(), ["lame", "kirsch"])
        self.assertEqual(t["N"].dtype, np.int64)
        self.assertEqual(t["N"].tolist(), [16, 32])
        self.assertEqual(t["seconds"].dtype, np.float64)
        self.assertEqual(t["seconds"].tolist(), [0.0125, 2.0])
        self.assertEqual(t["error"].tolist(), [0.035, -0.00001])
        self.assertEqual(t.select(t["case"] == "kirsch")["N"].tolist(), [32])

    def test_text_and_file(self):
        self.check(gembem.parse_csv(TEXT, "bench output"))
        path = os.path.join(self.tmp, "bench.csv")
        with open(path, "w") as f:
            f.write(TEXT)
        t = gembem.read_csv(path)
        self.check(t)
        self.assertEqual(t.path, path)

    def test_errors(self):
        with self.assertRaisesRegex(ValueError, r"bench output:5: 3 fields, expected 4"):
            gembem.parse_csv(TEXT.replace(",-1e-05", ""), "bench output")
        with self.assertRaisesRegex(ValueError, "bench output: empty file"):
            gembem.parse_csv("# nothing\n\n", "bench output")
        with self.assertRaisesRegex(KeyError, "no column 'err'"):
            gembem.parse_csv(TEXT)["err"]


class IterationForces(RunDirTest):
    def test_history(self):
        files = {"run_info.yaml": "status: completed\n",
                 "history.csv": "step,attempt,iteration,max_fixing_force\n1,1,1,50\n2,1,1,8\n2,1,2,0.5\n2,2,1,4\n",
                 "steps.csv": "step,max_fixing_force\n0,0\n1,0.25\n2,0.03125\n"}
        for name, text in files.items():
            with open(os.path.join(self.tmp, name), "w") as f:
                f.write(text)
        from gembem.figures import iteration_forces
        self.assertEqual(iteration_forces(gembem.Run(self.tmp), 2).tolist(), [8.0, 0.5, 4.0, 0.03125])
        self.assertEqual(iteration_forces(self.tmp, 1).tolist(), [50.0, 0.25])
        with self.assertRaisesRegex(ValueError, "no iteration of step 0"):
            iteration_forces(self.tmp, 0)


class SceneComment(RunDirTest):
    def test_comment(self):
        from gembem.yamlfile import read_yaml
        s = gembem.Scene(units={"length": "cm", "force": "kgf"}, solver={"accuracy": 0.475},
                         extra={"pack": {"count": 250, "solid_fraction": 0.876543}})
        path = s.write(os.path.join(self.tmp, "pack.yaml"), comment="case phi0.82\nline two")
        with open(path) as f:
            head = [f.readline() for _ in range(3)]
        self.assertEqual(head, ["# case phi0.82\n", "# line two\n", "# a gembem scene written by the gembem Python package\n"])
        self.assertEqual(read_yaml(path), {"gembem": 1, "units": {"length": "cm", "force": "kgf"},
                                           "solver": {"accuracy": 0.475},
                                           "pack": {"count": 250, "solid_fraction": 0.876543}})
        self.assertEqual(s.to_yaml(), s.to_yaml(comment=None))
        self.assertTrue(s.to_yaml().startswith("# a gembem scene written by the gembem Python package\ngembem: 1\n"))


if __name__ == "__main__":
    unittest.main()
