#!/usr/bin/python3
"""`python3 -m gembem scene IN -o OUT --set/--add/--delete`: a scene edited by its keys.

The hybrid scene of tests/hybrid/load_grains.yaml (a host mesh named relative to the scene's
directory) edited and written to another directory: a set (a word and a YAML flow map), an add, a
delete of a loading stage; `gembem run` reads the written scene (its mesh still found) and its
run_info.yaml settings, every setting as gembem's reader took it, hold the edited values. A key the
scene has not is refused for --set and --delete, one it has for --add: exit status 2, the key
named, no scene written; so are a key through a value that is no map and a value that is not YAML.
"""
import os
import pathlib
import subprocess
import sys
import unittest

import gembem
from common import RunDirTest
from gembem.yamlfile import read_yaml

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENE = ROOT / "tests" / "hybrid" / "load_grains.yaml"


def scene_command(*args):
    """The command as the shell tests call it; (exit status, stderr)."""
    p = subprocess.run([sys.executable, "-m", "gembem", "scene", *map(str, args)], capture_output=True, text=True,
                       env=dict(os.environ, PYTHONPATH=str(ROOT / "python")))
    return p.returncode, p.stderr


class SceneCommand(RunDirTest):
    def test_edits_read_by_gembem(self):
        out = f"{self.tmp}/edited/scene.yaml"
        code, err = scene_command(SCENE, "-o", out, "--set", "solver.linear=cholmod",
                                  "--set", "materials.grain_boundary={kn: 1000, kt: 500, friction_deg: 20}",
                                  "--set", "loading.2.host_load.steps=3", "--add", "output.measures_every=0",
                                  "--delete", "loading.0")
        self.assertEqual((code, err), (0, ""))
        written = gembem.Scene.load(out)
        self.assertEqual(written.solver["linear"], "cholmod")
        self.assertEqual(written.materials["grain_boundary"], {"kn": 1000, "kt": 500, "friction_deg": 20})
        self.assertEqual([k for stage in written.loading for k in stage], ["host_load", "host_load"])
        self.assertEqual(written.loading[1]["host_load"]["steps"], 3)
        self.assertEqual(written.output, {"measures_every": 0})
        self.assertEqual(written.host["mesh"], ROOT / "meshes" / "square_cavity_sides.geo")
        # what was not edited is as it was
        original = gembem.Scene.load(SCENE)
        self.assertEqual(written.grains, original.grains)
        self.assertEqual({k: v for k, v in written.solver.items() if k != "linear"},
                         {k: v for k, v in original.solver.items() if k != "linear"})
        # gembem run's reader: the settings it used are the edited ones
        run = gembem.run(written, f"{self.tmp}/run", quiet=True)
        self.assertEqual(run.status, "completed")
        settings = read_yaml(run.file("run_info.yaml"))["settings"]
        self.assertEqual(settings["solver"]["linear"], "cholmod")
        self.assertEqual(settings["materials"]["grain_boundary"],
                         {"kn": 1000, "kt": 500, "friction_deg": 20, "cohesion": 0})
        self.assertEqual([k for stage in settings["loading"] for k in stage], ["host_load", "host_load"])
        self.assertEqual([stage["host_load"]["steps"] for stage in settings["loading"]], [2, 3])
        self.assertEqual(len(run.steps["step"]), 1 + 2 + 3)
        self.assertFalse(os.path.exists(os.path.join(run.path, "fields")))   # measures_every: 0

    def test_missing_key_refused(self):
        for args, named in ((("--set", "solver.linear_solver=cholmod"), "solver.linear_solver"),
                            (("--set", "loading.5.relax.steps=2"), "loading.5"),
                            (("--set", "box.left=0"), "box"),
                            (("--delete", "solver.threads"), "solver.threads"),
                            (("--add", "solver.linear=cholmod"), "solver.linear"),
                            (("--add", "solver.linear.kind=cholmod"), "solver.linear.kind"),
                            (("--set", "solver.linear={cholmod"), "not YAML"),
                            (("--set", "solver.linear"), "KEY=VALUE")):
            with self.subTest(args=args):
                out = f"{self.tmp}/refused.yaml"
                code, err = scene_command(SCENE, "-o", out, "--set", "solver.accuracy=1e-8", *args)
                self.assertEqual(code, 2, err)
                self.assertIn(named, err)
                self.assertFalse(os.path.exists(out))

    def test_library(self):
        sc = gembem.Scene.load(SCENE)
        self.assertEqual(sc.value("host.boundary.left"), {"pressure": 0})
        self.assertEqual(sc.value("loading.-1.host_load.steps"), 2)
        self.assertFalse(sc.has("box") or sc.has("host.boundary.middle") or sc.has("loading.3"))
        cut = sc.without("host")
        self.assertIsNone(cut.host)
        self.assertIsNotNone(sc.host)   # a copy: the scene itself unchanged
        with self.assertRaises(KeyError) as e:
            sc.without("grains.file")
        self.assertEqual(e.exception.args, ("grains.file",))


if __name__ == "__main__":
    unittest.main()
