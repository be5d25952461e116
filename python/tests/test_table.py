#!/usr/bin/python3
"""gembem.table's one reader on hand-written CSV text: parse_csv (text a tool printed) and
read_csv (the same text in a file) give the same columns, each of the type its values need, with
the numbers written in the text; comments and blank lines are skipped; a short row is an error
naming its line."""
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


if __name__ == "__main__":
    unittest.main()
