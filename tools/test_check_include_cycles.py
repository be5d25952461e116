#!/usr/bin/python3
"""ctest tools_include_cycles_selftest: tools/check_include_cycles.py on tiny fake trees made here
(src/ and include/gembem/), with the cycles each one has written out by hand:
 - a -> b -> a (a/x.c includes "b/y.h", b/y.h includes "a/x.h"): found, exit 1;
 - a -> b -> c -> a and a -> c -> a: both found, once each, and nothing else;
 - an acyclic tree (a -> b, a -> c, b -> c), with includes of a file of the same folder, of
   <system> headers and of public headers that no folder implements: no cycle, exit 0;
 - a -> b -> a through a public header: b/y.c includes "gembem/a.h", whose function a/x.c
   defines, and a/x.c includes "b/y.h"; the same through a public header of types only
   (gembem/t.h) that includes gembem/a.h; and through gembem/b.h's own include of gembem/a.h;
 - a public header whose functions two folders define: reported (SPLIT), exit 1;
 - a tree of gembem's layers without a cycle, whose lowest layer (core) includes gem and with a
   folder the layers do not place: both reported (UPWARD, UNPLACED), exit 1;
 - bad usage: exit 2."""
import os
import subprocess
import sys
import tempfile
import unittest

TOOL = os.path.join(os.path.dirname(os.path.abspath(__file__)), "check_include_cycles.py")


def tree(root, files, bodies=None):
    """files: {"src/a/x.c": ["b/y.h", ...]}, each file holding one #include line per entry, then
    bodies.get(path) (declarations, definitions) or a variable."""
    for path, includes in files.items():
        full = os.path.join(root, path)
        os.makedirs(os.path.dirname(full), exist_ok=True)
        with open(full, "w") as f:
            f.write("/* fake */\n" + "".join(f'#include "{i}"\n' for i in includes) +
                    (bodies or {}).get(path, "int x;\n"))


def run(src, *args):
    p = subprocess.run([sys.executable, TOOL, src, *args], capture_output=True, text=True)
    return p.returncode, p.stdout


def reported(out, tag):
    return sorted(line[len(tag):].strip() for line in out.splitlines() if line.startswith(tag))


class IncludeCycles(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = self.tmp.name
        self.src = os.path.join(self.root, "src")
        os.makedirs(self.src)

    def tearDown(self):
        self.tmp.cleanup()

    def assert_cycles(self, cycles, *lines):
        """The check on self.src fails (exit 1) with exactly `cycles` and says each of `lines`;
        returns what it printed."""
        rc, out = run(self.src)
        self.assertEqual(rc, 1, out)
        self.assertEqual(reported(out, "CYCLE"), cycles)
        for line in lines:
            self.assertIn(line, out)
        return out

    def test_two_folders(self):
        tree(self.src, {"a/x.c": ["a/x.h", "b/y.h"], "a/x.h": [], "b/y.h": ["a/x.h"]})
        self.assert_cycles(["a -> b -> a"], "a -> b: a/x.c", "b -> a: b/y.h")

    def test_three_folders(self):
        tree(self.src, {"a/x.c": ["b/y.h", "c/z.h"], "b/y.h": ["c/z.h"], "c/z.h": ["a/x.h"], "a/x.h": []})
        self.assert_cycles(["a -> b -> c -> a", "a -> c -> a"])

    def test_no_cycle(self):
        tree(self.src, {"a/x.c": ["a/x.h", "b/y.h", "c/z.h", "gembem/status.h"], "a/x.h": ["gembem/scene.h"],
                        "b/y.h": ["c/z.h", "b/w.h"], "b/w.h": [], "c/z.h": ["c/v.h"], "c/v.h": []})
        with open(os.path.join(self.src, "c", "z.h"), "a") as f:
            f.write("#include <stdio.h>\n")
        rc, out = run(self.src)
        self.assertEqual(rc, 0, out)
        self.assertEqual(reported(out, "CYCLE"), [])
        self.assertIn("0 cycles", out)

    def test_public_header(self):
        # gembem/a.h declares a_f, which a/x.c defines: gembem/a.h is module a's.
        bodies = {"include/gembem/a.h": "typedef struct { int n; } a_t;\nint a_f(a_t *t);\n",
                  "src/a/x.c": "int a_f(a_t *t)\n{\n    return t->n;\n}\n"}
        tree(self.root, {"src/a/x.c": ["gembem/a.h", "b/y.h"], "src/b/y.h": [], "src/b/y.c": ["gembem/a.h"],
                         "include/gembem/a.h": []}, bodies)
        self.assert_cycles(["a -> b -> a"], "b -> a: b/y.c", "module of gembem/a.h: a")

    def test_public_header_of_types(self):
        # gembem/t.h declares no function: an include of it is one of gembem/a.h, which it includes.
        bodies = {"include/gembem/a.h": "int a_f(void);\n", "include/gembem/t.h": "typedef int t_t;\n",
                  "src/a/x.c": "int a_f(void) { return 0; }\n"}
        tree(self.root, {"src/a/x.c": ["gembem/a.h", "b/y.h"], "src/b/y.h": ["gembem/t.h"],
                         "include/gembem/a.h": [], "include/gembem/t.h": ["gembem/a.h"]}, bodies)
        self.assert_cycles(["a -> b -> a"], "b -> a: b/y.h", "module of gembem/t.h: none")

    def test_public_header_includes(self):
        # gembem/b.h (module b) includes gembem/a.h (module a): b -> a, made by gembem/b.h.
        bodies = {"include/gembem/a.h": "int a_f(void);\n", "include/gembem/b.h": "void b_f(int n);\n",
                  "src/a/x.c": "int a_f(void) { return 0; }\n", "src/b/y.c": "void b_f(int n) { (void)n; }\n"}
        tree(self.root, {"src/a/x.c": ["gembem/a.h", "gembem/b.h"], "src/b/y.c": ["gembem/b.h"],
                         "include/gembem/a.h": [], "include/gembem/b.h": ["gembem/a.h"]}, bodies)
        self.assert_cycles(["a -> b -> a"], "b -> a: gembem/b.h")

    def test_split_header(self):
        # gembem/a.h's functions are defined in a and in b (a static one of c and a function pointer
        # type do not count): one public header per module.
        bodies = {"include/gembem/a.h": "int a_f(void);\nint a_g(int n);\ntypedef int (*a_fn)(void);\n"
                                        "static inline int a_h(void) { return 1; }\n",
                  "src/a/x.c": "int a_f(void) { return 0; }\n",
                  "src/b/y.c": "int a_g(int n)\n{\n    return n;\n}\n",
                  "src/c/z.c": "static int a_h(void) { return 2; }\n"}
        tree(self.root, {"src/a/x.c": [], "src/b/y.c": [], "src/c/z.c": ["gembem/a.h"],
                         "include/gembem/a.h": []}, bodies)
        out = self.assert_cycles([], "1 public headers implemented in several folders")
        self.assertEqual(reported(out, "SPLIT"),
                         ["gembem/a.h: its functions are defined in 2 folders (a: a_f; b: a_g)"])

    def test_layers(self):
        # no cycle, but core (the lowest layer) includes gem, and a folder the layers do not place
        tree(self.src, {"core/x.c": ["gem/y.h"], "gem/y.h": [], "newthing/z.c": ["core/w.h"], "core/w.h": []})
        rc, out = run(self.src)
        self.assertEqual(rc, 1, out)
        self.assertEqual(reported(out, "CYCLE"), [])
        self.assertIn("UPWARD core -> gem: core/x.c", out)
        self.assertIn("UNPLACED newthing", out)
        tree(self.src, {"gem/v.c": ["core/w.h"]})  # downwards: fine
        self.assertNotIn("UPWARD gem", run(self.src)[1])

    def test_usage(self):
        self.assertEqual(run(self.src, "--bad")[0], 2)
        self.assertEqual(run(os.path.join(self.src, "missing"))[0], 2)
        self.assertEqual(run(self.src, os.path.join(self.root, "missing"))[0], 2)


if __name__ == "__main__":
    unittest.main()
