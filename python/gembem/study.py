"""Parameter studies: a table of cases, each packed, run by gembem, measured, gathered in one table.

A Study says what a case is (its scene, its packing, its measures); a workflow engine decides
what to run and where (studies/common.smk: Snakemake, which re-runs only what is missing or
changed, locally or on a cluster). Each step of a case is one function here, so that the engine
holds no logic of its own. A case's files, in its directory CASE/ (docs/studies.md):
grains.csv (packing), scene.yaml, run/ (gembem), status.yaml (how the run ended),
measures.yaml; the study's results.csv has one row per case, the missing ones with their status.
"""
import os
import time
from datetime import datetime, timezone
from dataclasses import dataclass, field

from .errors import GembemError
from .rundir import Run
from .runner import resume, run
from .table import read_csv
from .yamlfile import dump_yaml, read_yaml

# gembem's exit statuses that another attempt would only repeat (docs/run-directory.md): a
# refused scene, a step that did not converge. Any other failure (a kill, a full disk, out of
# memory) is raised, for the engine to retry.
FINAL = {0: "completed", 2: "scene refused", 3: "not converged"}


def read_cases(path):
    """The cases of a table: a CSV file (gembem.read_csv; one row per case) or a YAML list of
    maps; each case a dict with its name under ``case``. An empty CSV cell is left out."""
    path = os.fspath(path)
    if path.endswith((".yaml", ".yml")):
        rows = read_yaml(path)
    else:
        t = read_csv(path)
        rows = [{k: t[k][i].item() for k in t if str(t[k][i]) != ""} for i in range(t.nrows)]
    if not isinstance(rows, list) or not all(isinstance(r, dict) and "case" in r for r in rows):
        raise ValueError(f"{path}: expected one case per row, each with a 'case' name")
    return rows


def steps_measures(r):
    """The default measures of a run: its last step, the iterations and seconds of all steps."""
    s = r.steps
    return {"last_step": int(s["step"][-1]), "iterations": int(s["iterations"].sum()),
            "seconds": float(s["seconds"].sum())}


@dataclass
class Study:
    """A table of cases and what to do with each.

    cases: a list of dicts (each with its name under ``case``) or the path of a table (read_cases).
      A column whose name has a dot (``solver.max_iterations``, ``loading.2.shear_mean_stress.steps``)
      is set in the case's scene (Scene.with_value); the others are the study's own parameters.
    scene(case, case_dir): the case's Scene (or its YAML text); its file names relative to case_dir.
    scene_inputs: the files the scenes are made from (a base scene): a change re-runs every case.
    pack(case, case_dir): writes the case's packing, case_dir/``pack_output``; it depends on the
      columns ``pack_keys`` only (a change of another column keeps the packing).
    measure(Run) -> dict of numbers, for a run whose status is in ``measured`` (default: completed
      runs; a study whose stopped runs mean something adds "not converged"); default steps_measures.
    retries: attempts after the first for a run that fails otherwise than by FINAL (a killed run
      resumes from its checkpoint). threads: per run (OpenBLAS's). resources: the engine's per run
      (runtime in minutes, times the attempt; mem_mb), for a cluster's scheduler.
    """
    cases: object
    scene: object
    scene_inputs: list = field(default_factory=list)
    pack: object = None
    pack_keys: tuple = ()
    pack_output: str = "grains.csv"
    measure: object = steps_measures
    measured: tuple = ("completed",)
    retries: int = 2
    threads: int = 1
    resources: dict = field(default_factory=lambda: {"runtime": 60, "mem_mb": 2000})

    def __repr__(self):
        names = [str(c.get("case")) for c in self.cases]
        shown = ", ".join(names[:5]) + (f", ... ({len(names) - 5} more)" if len(names) > 5 else "")
        columns = sorted({k for c in self.cases for k in c} - {"case"})
        return f"Study({len(names)} cases: {shown}; columns: {', '.join(columns) or 'none'})"

    def __post_init__(self):
        if not isinstance(self.cases, list):
            self.cases = read_cases(self.cases)
        self._by_name = {}
        for c in self.cases:
            name = str(c["case"])
            if not name or "/" in name or name in self._by_name:
                raise ValueError(f"case '{name}': expected a unique name, usable as a directory name")
            self._by_name[name] = c

    def names(self):
        return list(self._by_name)

    def case(self, name):
        return self._by_name[name]

    def pack_params(self, name):
        """What the packing depends on: a change of it re-packs the case."""
        return {k: self.case(name).get(k) for k in self.pack_keys}

    def write_pack(self, name, case_dir):
        os.makedirs(case_dir, exist_ok=True)
        self.pack(self.case(name), case_dir)

    def write_scene(self, name, path):
        """The case's scene written to path: the study's scene with the case's dotted columns set."""
        case = self.case(name)
        scene = self.scene(case, os.path.dirname(os.path.abspath(path)))
        over = {k: v for k, v in case.items() if "." in k}
        if isinstance(scene, str):
            if over:
                raise ValueError(f"case {name}: columns {sorted(over)} set scene values, but the study's "
                                 "scene is YAML text; expected a gembem.Scene")
            os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
            with open(path, "w") as f:
                f.write(scene)
            return path
        for k, v in over.items():
            scene = scene.with_value(k, v)
        return scene.write(path)

    def run_case(self, name, scene_path, status_path, attempt=1, run_dir=None):
        """Runs the case's scene into run_dir (default: run/ beside the status file) and writes the
        status file; a failure that is not FINAL is raised unless this is the last attempt, when
        it is written down too. A run of this scene that was killed is resumed, not restarted."""
        run_dir = run_dir or os.path.join(os.path.dirname(status_path), "run")
        env = {"OPENBLAS_NUM_THREADS": str(self.threads)}
        t0 = time.time()
        try:
            if _resumable(run_dir, scene_path):
                resume(run_dir, quiet=True, env=env)
            else:
                run(scene_path, run_dir, overwrite=True, quiet=True, env=env)
            code, message = 0, ""
        except GembemError as e:
            if e.returncode not in FINAL and attempt <= self.retries:
                raise
            code, message = e.returncode, e.message
        # `finished` makes every run's status file new: Snakemake 7 takes an input file whose
        # checksum it has seen before as not updated, so a run that ended with the status of the
        # one it replaced (the same seconds to the millisecond, about 1 case in 20 of the tiny
        # study's on a loaded machine) left measure and results skipped and their old files
        # touched as new.
        status = {"case": name, "status": FINAL.get(code, "failed"), "exit": code, "message": message,
                  "attempt": attempt, "run": os.path.basename(run_dir), "seconds": round(time.time() - t0, 3),
                  "finished": datetime.now(timezone.utc).isoformat(timespec="microseconds")}
        _write_yaml(status_path, status)
        return status

    def measure_case(self, status_path, out):
        """The case's status and, for a run whose status is measured, its measures, written to out."""
        status = read_yaml(status_path)
        doc = dict(status)
        if status["status"] in self.measured:
            r = Run(os.path.join(os.path.dirname(status_path), status["run"]))
            doc["measures"] = {k: _plain(v) for k, v in self.measure(r).items()}
        _write_yaml(out, doc)

    def aggregate(self, out, case_dir=lambda name: name):
        """results.csv: one row per case in table order: name, status, exit code, attempt, the
        case's columns, its measures; a case without measures.yaml is 'missing' (its run or an
        earlier step failed: see the engine's log). Returns the rows."""
        rows = []
        for name in self.names():
            path = os.path.join(case_dir(name), "measures.yaml")
            doc = read_yaml(path) if os.path.exists(path) else {"status": "missing", "exit": "", "attempt": ""}
            row = {"case": name, "status": doc["status"], "exit": doc["exit"], "attempt": doc["attempt"]}
            row.update({k: v for k, v in self.case(name).items() if k != "case"})
            for k, v in doc.get("measures", {}).items():
                if k in row:
                    raise ValueError(f"measure '{k}' has the name of a column of the case table")
                row[k] = v
            rows.append(row)
        columns = list(dict.fromkeys(k for r in rows for k in r))
        tmp = out + ".tmp"
        with open(tmp, "w") as f:
            f.write(",".join(columns) + "\n")
            for r in rows:
                f.write(",".join(_cell(r.get(k, "")) for k in columns) + "\n")
        os.replace(tmp, out)
        return rows


def _resumable(run_dir, scene_path):
    """A run killed, interrupted (a signal) or stopped by a full disk, started from this scene file as it is now (the
    scene rewritten since, e.g. for a new packing of the same name, is a new run)."""
    info, copy = os.path.join(run_dir, "run_info.yaml"), os.path.join(run_dir, "scene.yaml")
    return (os.path.exists(os.path.join(run_dir, "checkpoint.txt")) and os.path.exists(info)
            and os.path.exists(copy) and os.path.getmtime(copy) >= os.path.getmtime(scene_path)
            and read_yaml(info).get("status") in ("running", "interrupted", "i/o error"))


def _write_yaml(path, doc):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(dump_yaml(doc, block=True))
    os.replace(tmp, path)


def _plain(v):
    return v.item() if hasattr(v, "item") else v


def _cell(v):
    """A CSV cell: floats by repr (exact), text quoted when it holds a comma or a quote."""
    s = repr(v) if isinstance(v, float) else str(v)
    return '"' + s.replace('"', '""') + '"' if any(c in s for c in ',"\n') else s
