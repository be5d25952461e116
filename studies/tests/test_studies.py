#!/usr/bin/python3
"""The studies' workflows, on the biaxial study (validation/biaxial122/Snakefile) with tiny cases
(tiny_cases.csv: 30 grains, 10 shear steps, seconds each).

ctest study_tiny (StudyTiny): the study run by `snakemake -j 2` end to end.

- results.csv equals what each run's own steps.csv says (read here, not through stats.py): peak
  s1/s2 and the shear strain there, the volumetric strain at the end, iterations, seconds; case
  `fail` (10 iterations a step) is there with its status, not converged (exit 3), as its run says.
- A second invocation has nothing to do; a changed column of case b re-runs b's scene and run,
  not its packing, and nothing of a or fail.
- A run killed (gembem's test hook GB_TEST_KILL_AT) is retried and resumes from its checkpoint
  to the same numbers; killed at every attempt it is reported `failed`, exit -9, attempt 3.
- A packing that fails stops the workflow, and results.csv says the case is missing.
- A forced re-run without --force-use-threads is refused (Snakemake 7.21 would skip it).

ctest study_slurm_profile (SlurmProfile): studies/profiles/slurm, without Slurm. Its dry run lists
the jobs with the resources they would ask for; then the study runs through it with stand-ins for
sbatch and sacct (mock_slurm/: each job run at once): one sbatch per packing and per run, with the
cpus, memory and time of its rule, the cheap steps run locally, every case completed.

Skipped (exit 77) when snakemake is not installed (tools/setup.sh installs it).
"""
import os
import shutil
import subprocess
import sys
import unittest

import numpy as np

import gembem
from gembem.yamlfile import read_yaml

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
SNAKEFILE = os.path.join(ROOT, "validation", "biaxial122", "Snakefile")
BUILD = os.environ.get("GB_BUILD", os.path.join(ROOT, "build"))
KILL_MID_RUN = 180   # gembem's 180th output write: within case a's run (about 245), more than a resume needs


def expected(run_dir):
    """The numbers of a run from its steps.csv: peak s1/s2 in the shear (the last stage), ..."""
    s = gembem.read_csv(os.path.join(run_dir, "steps.csv"))
    shear = s.select(s["stage"] == s["stage"].max())
    ratio = shear["s1"] / shear["s2"]
    k = int(np.argmax(ratio))
    return {"peak_ratio": ratio[k], "peak_strain": 100 * shear["e1_minus_e2"][k], "ev_end": 100 * shear["ev"][-1],
            "iterations": shear["iterations"].mean(), "seconds": s["seconds"].sum(), "last_step": s["step"][-1]}


class StudyTest(unittest.TestCase):
    """A fresh directory per test (kept after it, to look at), the tiny cases copied there."""
    def setUp(self):
        self.tmp = os.path.join(os.environ.get("GB_TEST_DIR", "/tmp"), type(self).__name__)
        shutil.rmtree(self.tmp, ignore_errors=True)
        os.makedirs(self.tmp)
        self.cases = os.path.join(self.tmp, "cases.csv")
        shutil.copy(os.path.join(HERE, "tiny_cases.csv"), self.cases)
        self.out = os.path.join(self.tmp, "out")

    def snakemake(self, *args, env=None, ok=True):
        cmd = ["snakemake", "-s", SNAKEFILE, "-j", "2", *args, "--config", f"cases={self.cases}",
               f"out={self.out}", f"build={BUILD}"]
        p = subprocess.run(cmd, capture_output=True, text=True, env=dict(os.environ, **(env or {})))
        if ok and p.returncode != 0:
            self.fail(f"{' '.join(cmd)}: exit {p.returncode}\n{p.stderr[-4000:]}")
        return p

    def results(self):
        t = gembem.read_csv(os.path.join(self.out, "results.csv"))
        return {str(t["case"][i]): {k: t[k][i] for k in t} for i in range(t.nrows)}

    def mtime(self, path):
        return os.stat(os.path.join(self.out, path)).st_mtime_ns



class StudyTiny(StudyTest):
    def check_completed(self, row, case):
        run = os.path.join(self.out, case, "run")
        self.assertEqual(row["status"], "completed")
        self.assertEqual(gembem.Run(run).status, "completed")
        for k, v in expected(run).items():
            if k != "last_step":
                self.assertAlmostEqual(float(row[k]), v, delta=1e-12 * abs(v), msg=f"{case} {k}")
        return expected(run)

    def test_study(self):
        self.snakemake()
        res = self.results()
        self.assertEqual(list(res), ["a", "b", "fail"])
        for case in ("a", "b"):
            self.assertEqual(self.check_completed(res[case], case)["last_step"], 20)   # 1 + 9 + 10 steps
            self.assertEqual(int(res[case]["n"]), 30)
        self.assertEqual((res["fail"]["status"], int(res["fail"]["exit"])), ("not converged", 3))
        self.assertEqual(str(res["fail"]["peak_ratio"]), "")
        self.assertEqual(gembem.Run(os.path.join(self.out, "fail", "run")).status, "not converged")
        with open(os.path.join(self.out, "stats.md")) as f:
            self.assertIn("| fail | not converged |", f.read())

        # Nothing changed: nothing to do.
        self.assertIn("Nothing to be done", self.snakemake().stderr)

        # One column of case b changed: b's scene and run again, not its packing, nor a's or fail's.
        before = {p: self.mtime(p) for p in ("a/status.yaml", "fail/status.yaml", "b/grains.csv", "b/status.yaml")}
        with open(self.cases) as f:
            text = f.read()
        with open(self.cases, "w") as f:
            f.write(text.replace("b,30,2,10,", "b,30,2,8,"))
        log = self.snakemake().stderr
        self.assertEqual(log.count("rule run:"), 1, log)
        for p in ("a/status.yaml", "fail/status.yaml", "b/grains.csv"):
            self.assertEqual(self.mtime(p), before[p], p)
        self.assertGreater(self.mtime("b/status.yaml"), before["b/status.yaml"])
        res = self.results()
        self.assertEqual(self.check_completed(res["b"], "b")["last_step"], 18)
        a_before = res["a"]

        # Killed mid-run: retried, resumed from the checkpoint, the same numbers.
        self.assertNotEqual(self.snakemake("-R", "a/status.yaml", ok=False).returncode, 0)   # refused
        log = self.snakemake("-R", "a/status.yaml", "--force-use-threads", env={"GB_TEST_KILL_AT": str(KILL_MID_RUN)}).stderr
        self.assertIn("Trying to restart", log)
        status = read_yaml(os.path.join(self.out, "a", "status.yaml"))
        self.assertEqual((status["status"], status["attempt"]), ("completed", 2))
        self.assertIn("resumed", gembem.Run(os.path.join(self.out, "a", "run")).run_info)
        res = self.results()
        self.check_completed(res["a"], "a")
        for k in ("peak_ratio", "peak_strain", "ev_end", "porosity", "balance", "books"):
            self.assertEqual(res["a"][k], a_before[k], k)

        # Killed at every attempt: reported, not dropped.
        self.snakemake("-R", "a/status.yaml", "--force-use-threads", env={"GB_TEST_KILL_AT": "1"})
        row = self.results()["a"]
        self.assertEqual((row["status"], int(row["exit"]), int(row["attempt"])), ("failed", -9, 3))

        # A packing that fails (no grains): the workflow stops, the table names the case missing.
        with open(self.cases, "a") as f:
            f.write("nopack,0,1,10,5000000\n")
        p = self.snakemake("--keep-going", ok=False)
        self.assertNotEqual(p.returncode, 0)
        res = self.results()
        self.assertEqual(res["nopack"]["status"], "missing")
        self.assertEqual(res["b"]["status"], "completed")


class SlurmProfile(StudyTest):
    def test_profile(self):
        with open(self.cases) as f:
            lines = f.read().splitlines()[:3]   # cases a and b
        with open(self.cases, "w") as f:
            f.write("\n".join(lines) + "\n")
        profile = ["--profile", os.path.join(ROOT, "studies", "profiles", "slurm")]
        log = self.snakemake("-n", *profile).stdout
        for rule, resources in (("pack", "runtime=10"), ("run", "runtime=30")):
            jobs = [j for j in log.split("\n\n") if f"\nrule {rule}:" in j]
            self.assertEqual(len(jobs), 2, log)
            self.assertTrue(all(resources in j and "mem_mb=1000" in j for j in jobs), jobs)
        self.assertEqual(log.count("localrule scene:"), 2)

        mock = os.path.join(self.tmp, "mock")
        os.makedirs(mock)
        env = {"PATH": os.path.join(HERE, "mock_slurm") + os.pathsep + os.environ["PATH"], "MOCK_SLURM": mock}
        self.snakemake(*profile, "--max-status-checks-per-second", "10", env=env)
        with open(os.path.join(mock, "submissions.txt")) as f:
            submitted = sorted(f.read().splitlines())
        self.assertEqual(len(submitted), 4, submitted)
        for line, (rule, case, minutes) in zip(submitted, [("pack", "a", 10), ("pack", "b", 10), ("run", "a", 30),
                                                          ("run", "b", 30)]):
            self.assertIn(f"--job-name=gembem-{rule}-case={case} --cpus-per-task=1 --mem=1000 --time={minutes} ", line)
        self.assertEqual([str(s) for s in gembem.read_csv(os.path.join(self.out, "results.csv"))["status"]],
                         ["completed", "completed"])


if __name__ == "__main__":
    if shutil.which("snakemake") is None:
        print("study_tiny skipped: no snakemake (Debian's snakemake; tools/setup.sh installs it)")
        sys.exit(77)
    unittest.main()
