#!/usr/bin/python3
"""Every reader on a hybrid run, and every standard figure drawn from it.

tests/hybrid/load_grains.yaml (27 grains in the cavity of an elastic square, a confining
pressure, then the top pushed) loaded with Scene.load, its mesh path made absolute, written
elsewhere with the iteration history and the per-contact files asked for, and run. Checks that
the readers agree with each other and with mechanics: the grains' forces on the boundary
particles equal the host's (host_particles.csv), one row per step in steps, localisation and
fields/, per group in host_steps, one particle per cavity element in the state; the host field's
mesh is whole. Then each figure of gembem.figures is drawn, saved and its content counted; a
torn CSV row is an error naming its line; large objects print as one short line. Run again with
a progress callback, the scene's progress lines (a host's have no stress ratio) reach it once per
step and none leaks to stderr.
"""
import os
import unittest

import numpy as np

import gembem
import gembem.figures as figures
from common import RunDirTest

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


class ReadersFigures(RunDirTest):
    @classmethod
    def setUpClass(cls):
        import tempfile
        cls.dir = tempfile.mkdtemp(prefix="gembem_ReadersFigures_run_")
        sc = gembem.Scene.load(os.path.join(ROOT, "tests", "hybrid", "load_grains.yaml"))
        sc.solver = dict(sc.solver, history=True)
        sc.output = {"contacts_every": 1, "snapshot_every": 2}
        cls.rd = gembem.run(sc, os.path.join(cls.dir, "run"), quiet=True)

    @classmethod
    def tearDownClass(cls):
        import shutil
        shutil.rmtree(cls.dir, ignore_errors=True)

    def test_tables(self):
        run = self.rd
        n = run.steps.nrows
        self.assertEqual(n, 1 + 1 + 2 + 2)                         # step 0, relax, 2 + 2 host loads
        self.assertEqual(list(run.localisation["step"]), list(range(n)))
        self.assertEqual(list(run.micromechanics["step"]), list(range(n)))
        self.assertEqual(run.steps_of("fields", "grains"), list(range(n)))
        self.assertEqual(run.steps_of("contacts", "contacts"), list(range(n)))
        groups = sorted(set(run.host_steps["group"]))
        self.assertEqual(groups, ["bottom", "cavity", "left", "right", "top"])
        self.assertEqual(run.host_steps.nrows, n * len(groups))
        p = run.host_particles
        scale = np.abs(p["host_fx"]).max()
        np.testing.assert_allclose(p["grain_fx"], p["host_fx"], atol=1e-8 * scale)
        np.testing.assert_allclose(p["grain_fy"], p["host_fy"], atol=1e-8 * scale)
        self.assertGreater(run.history.nrows, 0)
        self.assertTrue(set(run.history["step"]) <= set(range(1, n)))
        self.assertEqual(run.status, "completed")
        rec = run.steps.records()
        self.assertEqual(rec["max_fixing_force"][-1], run.steps["max_fixing_force"][-1])
        self.assertTrue(np.isnan(run.steps["s1"]).all())   # a host has no walls: the box columns are undefined

    def test_every_file(self):
        # Every file gembem left is read by one of the package's readers (one CSV reader for all).
        from gembem.yamlfile import read_yaml
        from gembem.rundir import read_lock
        readers = {"csv": gembem.read_csv, "vtu": gembem.read_vtk, "vtp": gembem.read_vtk,
                   "pvd": gembem.read_pvd, "yaml": read_yaml, "lock": read_lock}
        count = 0
        for root, _, files in os.walk(self.rd.path):
            for f in files:
                ext = f.rsplit(".", 1)[-1]
                self.assertIn(ext, readers, f"{root}/{f}: no reader for it")
                readers[ext](os.path.join(root, f))
                count += 1
        self.assertGreater(count, 50)
        # the lock file: its writer is gone, and it recorded how the run ended
        holder = self.rd.holder
        self.assertEqual((holder["status"], holder["live"]), ("completed", False))
        self.assertGreater(int(holder["pid"]), 0)

    def test_state(self):
        st = self.rd.state
        self.assertEqual(st.grains.nrows, 27)
        self.assertEqual(st.host_particles.nrows, st.host["cavity_elements"])
        self.assertEqual(st.host["boundary"]["left"], {"pressure": 20})    # 2 steps of +10
        # The last step's contacts file is the final state's contacts.
        last = self.rd.contacts(self.rd.steps["step"][-1])
        np.testing.assert_array_equal(last["pn"], st.contacts["pn"])
        self.assertTrue(any(j.startswith("p") for j in st.contacts["j"]))  # boundary particles

    def test_snapshots(self):
        steps = self.rd.steps_of("snapshots", "grains", "vtp")
        self.assertEqual(steps, [0, 2, 4])
        pvd = gembem.read_pvd(self.rd.file("grains.pvd"))
        self.assertEqual([int(t) for t, _ in pvd], steps)
        self.assertEqual(pvd[-1][1], os.path.join(os.path.abspath(self.rd.path), "snapshots", "grains_000004.vtp"))
        g, snap = self.rd.grains(4), self.rd.snapshot("grains", 4)
        np.testing.assert_allclose(snap.points[:, 0], g["x"], rtol=1e-9, atol=1e-12)
        np.testing.assert_allclose(snap.point_data["radius"], g["r"], rtol=1e-9)
        c, lines = self.rd.contacts(4), self.rd.snapshot("contacts", 4)
        contact = lines.cell_data["kind"] != 2                # kind 2: the box's four sides
        self.assertEqual(len(lines.cells()), c.nrows + 4)
        np.testing.assert_allclose(np.sort(lines.cell_data["pn"][contact]), np.sort(c["pn"]), rtol=1e-9)

    def test_host_field(self):
        m = self.rd.host_field()
        t = m.triangles()
        self.assertEqual(t.shape[1], 3)
        self.assertEqual(t.max(), len(m.points) - 1)
        self.assertEqual(m.point_data["stress"].shape, (len(m.points), 9))
        np.testing.assert_array_equal(m.point_data["stress"][:, 0], m.point_data["sxx"])

    def test_figures(self):
        out = os.path.join(self.dir, "figures")
        os.makedirs(out, exist_ok=True)
        run, last = self.rd, int(self.rd.steps["step"][-1])
        made = {
            "force_chains": figures.force_chains(run, path=f"{out}/force_chains.png"),
            "force_chains_step": figures.force_chains(run, step=2, path=f"{out}/force_chains_2.png"),
            "stress_strain": figures.stress_strain(run, x="ev", y="s1", path=f"{out}/stress_strain.png"),
            "load_displacement": figures.load_displacement(run, path=f"{out}/load_displacement.png"),
            "convergence": figures.convergence(run, int(run.history["step"][0]), path=f"{out}/convergence.png"),
            "rose": figures.rose(run, last, path=f"{out}/rose.png"),
            "host_stress": figures.host_stress(run, path=f"{out}/host_stress.png"),
            "strain_map": figures.strain_map(run, last, path=f"{out}/strain_map.png"),
        }
        for name in made:
            files = [f for f in os.listdir(out) if f.startswith(name.replace("_step", ""))]
            self.assertTrue(files, name)
            for f in files:
                with open(os.path.join(out, f), "rb") as fh:
                    self.assertEqual(fh.read(8), b"\x89PNG\r\n\x1a\n", f)
        self.assertEqual(figures.loaded_group(run), ("top", "y"))   # pushed down by 0.002, sideways by 0.001
        # force chains: one line per contact, the widest the largest normal force
        lines = [c for c in made["force_chains"].axes[0].collections if hasattr(c, "get_segments")]
        self.assertEqual(len(lines[0].get_segments()), run.state.contacts.nrows)
        self.assertAlmostEqual(max(lines[0].get_linewidths()), 6.0)
        # convergence: the step's iterations and its converged force
        h = run.history
        step = int(h["step"][0])
        curve = made["convergence"].axes[0].lines[0].get_ydata()
        self.assertEqual(len(curve), np.count_nonzero(h["step"] == step) + 1)
        # strain map: one coloured triangle per triangle of the step's field, the grains outlined
        faces = made["strain_map"].axes[0].collections[0].get_array()
        self.assertEqual(len(faces), self.rd.localisation["triangles"][last])
        with self.assertRaises(ValueError):
            figures.host_stress(run, component="nothing")

    def test_command_line(self):
        from gembem.__main__ import main
        out = os.path.join(self.tmp, "figures")
        self.assertEqual(main(["figures", self.rd.path, out]), 0)
        made = sorted(os.listdir(out))
        last = int(self.rd.steps["step"][-1])
        for name in ("force_chains.png", "host_stress.png", f"rose_{last:06d}.png", f"strain_map_{last:06d}.png",
                     "cavity_wall.png", "localisation_index.png"):
            self.assertIn(name, made)
        self.assertNotIn("stress_strain.png", made)          # a hybrid run has no box stresses
        self.assertTrue(any(n.startswith("convergence_") for n in made))
        self.assertTrue(any(n.startswith("load_displacement_") for n in made))
        self.assertEqual(main(["figures", self.tmp]), 1)      # not a run directory: a message, status 1

    def test_progress(self):
        # A hybrid scene's progress lines (no stress ratio) reach the callback, one per step, and
        # nothing reaches stderr: the same scene, the load steps counted from the scene (1 + 2 + 2).
        import contextlib
        import io
        seen, err, out = [], io.StringIO(), io.StringIO()
        with contextlib.redirect_stderr(err), contextlib.redirect_stdout(out):
            gembem.run(os.path.join(ROOT, "tests", "hybrid", "load_grains.yaml"), f"{self.tmp}/run",
                       progress=seen.append, quiet=False)
        self.assertEqual([p.step for p in seen], list(range(6)))
        self.assertTrue(all(p.total == 5 and np.isnan(p.stress_ratio) for p in seen))
        self.assertEqual(err.getvalue(), "")
        self.assertIn("5 steps", out.getvalue())       # gembem's summary, on stdout

    def test_repr(self):
        # Large objects print as one short line with their sizes, not their arrays.
        run = self.rd
        m, st = run.host_field(), run.state
        scene = gembem.Scene.load(os.path.join(ROOT, "tests", "hybrid", "load_grains.yaml"))
        from gembem.study import Study
        cases = Study([{"case": f"c{k}", "phi": k} for k in range(40)], scene=None)
        for obj, has in ((m, f"{len(m.points)} points, {len(m.offsets)} cells"),
                         (run.snapshot("grains", 4), "27 points"),
                         (st, f"27 grains, {st.contacts.nrows} contacts"), (run.steps, f"{run.steps.nrows} rows"),
                         (scene, "grains (27 grains)"), (cases, "40 cases"), (run, run.path)):
            text = repr(obj)
            self.assertIn(has, text)
            self.assertLess(len(text), 600, text)
            self.assertNotIn("\n", text)

    def test_torn_row(self):
        src = self.rd.file("steps.csv")
        torn = os.path.join(self.tmp, "steps.csv")
        with open(src) as f:
            text = f.read()
        with open(torn, "w") as f:
            f.write(text[: text.rindex(",")])        # the last row cut short, as a killed run leaves it
        n = text.splitlines()[0].count(",") + 1     # the header's columns; the torn row has one fewer
        with self.assertRaisesRegex(ValueError, rf"steps\.csv:7: {n - 1} fields, expected {n}"):
            gembem.read_csv(torn)
        with self.assertRaisesRegex(KeyError, "no column 'sigma'"):
            self.rd.steps["sigma"]
        with self.assertRaisesRegex(FileNotFoundError, "not a run directory"):
            gembem.Run(self.tmp)


if __name__ == "__main__":
    unittest.main()
