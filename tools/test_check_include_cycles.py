#!/usr/bin/python3
"""ctest tools_include_cycles_selftest: tools/check_include_cycles.py on tiny fake src/ trees made
here, with the cycles each one has written out by hand:
 - a -> b -> a (a/x.c includes "b/y.h", b/y.h includes "a/x.h"): found, exit 1;
 - a -> b -> c -> a and a -> c -> a: both found, once each, and nothing else;
 - an acyclic tree (a -> b, a -> c, b -> c), with includes of a file of the same folder, of
   <system> headers and of folders not in src/ ("gembem/...", as include/gembem/): no cycle, exit 0;
 - bad usage: exit 2."""
import os
import subprocess
import sys
import tempfile
import unittest

TOOL = os.path.join(os.path.dirname(os.path.abspath(__file__)), "check_include_cycles.py")


def tree(root, files):
    """files: {"a/x.c": ["b/y.h", ...]}, each file holding one #include line per entry."""
    for path, includes in files.items():
        full = os.path.join(root, path)
        os.makedirs(os.path.dirname(full), exist_ok=True)
        with open(full, "w") as f:
            f.write("/* fake */\n" + "".join(f'#include "{i}"\n' for i in includes) + "int x;\n")


def run(src, *args):
    p = subprocess.run([sys.executable, TOOL, src, *args], capture_output=True, text=True)
    return p.returncode, p.stdout


def reported(out, tag):
    return sorted(line[len(tag):].strip() for line in out.splitlines() if line.startswith(tag))


class IncludeCycles(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.src = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def test_two_folders(self):
        tree(self.src, {"a/x.c": ["a/x.h", "b/y.h"], "a/x.h": [], "b/y.h": ["a/x.h"]})
        rc, out = run(self.src)
        self.assertEqual(rc, 1, out)
        self.assertEqual(reported(out, "CYCLE"), ["a -> b -> a"])
        self.assertIn("a -> b: a/x.c", out)
        self.assertIn("b -> a: b/y.h", out)

    def test_three_folders(self):
        tree(self.src, {"a/x.c": ["b/y.h", "c/z.h"], "b/y.h": ["c/z.h"], "c/z.h": ["a/x.h"], "a/x.h": []})
        rc, out = run(self.src)
        self.assertEqual(rc, 1, out)
        self.assertEqual(reported(out, "CYCLE"), ["a -> b -> c -> a", "a -> c -> a"])

    def test_no_cycle(self):
        tree(self.src, {"a/x.c": ["a/x.h", "b/y.h", "c/z.h", "gembem/status.h"], "a/x.h": ["gembem/scene.h"],
                        "b/y.h": ["c/z.h", "b/w.h"], "b/w.h": [], "c/z.h": ["c/v.h"], "c/v.h": []})
        with open(os.path.join(self.src, "c", "z.h"), "a") as f:
            f.write("#include <stdio.h>\n")
        rc, out = run(self.src)
        self.assertEqual(rc, 0, out)
        self.assertEqual(reported(out, "CYCLE"), [])
        self.assertIn("0 cycles", out)

    def test_usage(self):
        self.assertEqual(run(self.src, "--bad")[0], 2)
        self.assertEqual(run(os.path.join(self.src, "missing"))[0], 2)


if __name__ == "__main__":
    unittest.main()
