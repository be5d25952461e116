"""gembem from Python: build a scene, run it, read its run directory, draw the standard figures.

    import gembem
    scene = gembem.Scene.load("validation/three_discs/case1.yaml")
    run = gembem.run(scene.with_value("materials.grain_grain.friction_deg", 25), "runs/phi25")
    run.steps["stress_ratio"], run.state.contacts["pn"]

    sim = gembem.Simulation("validation/three_discs/case1.yaml")   # the library, in this process
    sim.step(); sim.run_stage(); sim.grains["x"], sim.contacts["pn"]

Modules: scene (Scene, YAML writing), runner (run, resume, find_gembem, Progress), library
(Simulation, StepReport: libgembem through ctypes, a step at a time, arrays between steps), errors
(GembemError and one class per exit status), table (read_csv, parse_csv, Table), state (read_state),
rundir (Run, Packing, open_directory), vtk (read_vtk, read_pvd), figures (matplotlib, imported on demand).
Dependencies: Debian's python3-numpy, python3-yaml; python3-matplotlib for figures.
"""
from .errors import ConvergenceError, GembemError, OutputError, SceneError
from .library import Simulation, StepReport
from .rundir import Packing, Run, open_directory
from .runner import Progress, find_gembem, resume, run
from .scene import Scene, write_grains_csv
from .state import State, read_state
from .table import Table, parse_csv, read_csv
from .vtk import read_pvd, read_vtk

__all__ = ["ConvergenceError", "GembemError", "OutputError", "SceneError", "Run", "Packing", "open_directory",
           "Progress", "find_gembem", "resume", "run", "Scene", "write_grains_csv", "State", "read_state", "Table",
           "parse_csv", "read_csv", "read_pvd", "read_vtk", "Simulation", "StepReport"]
