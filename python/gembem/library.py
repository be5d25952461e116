"""gembem's library in this process (ctypes and numpy, no compiled extension): a scene loaded from
a file or built from Python objects, its simulation taken one load step, one stage or the whole
loading program at a time, and the grains, contacts, walls and host read as numpy arrays between
steps, with no files in between.

    sim = gembem.Simulation("validation/three_discs/case1.yaml")   # or a gembem.Scene
    sim.step()                       # step 0, the initial state; each next call: one load step
    sim.run_stage()                  # to the end of the stage of the next step
    g, c = sim.grains, sim.contacts  # Tables: x, y, r, rotation; i, j, pn, pt, sliding, ...
    sim.run()                        # the rest of the loading program
    sim.write_state("runs/py")       # state.yaml and its CSV files, as `gembem run` writes them

The simulation is the library's own (gb_sim_create, gb_run_create, gb_run_advance, gembem/run.h): a
run by steps here gives the states `gembem run` gives. A failure of the library raises the exception
of its status (gembem.errors: SceneError with gembem's file:line:column, ConvergenceError, ...).

The library: the `library=` argument, else $GEMBEM_LIBRARY, else the one installed with this
package (cmake --install, the .deb), else this checkout's build/src/libgembem.so.0.
"""
import ctypes
import os
from dataclasses import dataclass

import numpy as np

from .errors import error_for
from .table import Table

SONAME = "libgembem.so.0"
_HERE = os.path.dirname(os.path.abspath(__file__))
_BUILD_TREE = os.path.normpath(os.path.join(_HERE, "..", "..", "build", "src", SONAME))
try:  # written by cmake --install: the installed library relative to this installed package
    from ._paths import LIBDIR as _LIBDIR
    _INSTALLED = os.path.join(_LIBDIR, SONAME)
except ImportError:  # this package in a checkout
    _INSTALLED = None

# The walls in gembem's order (GB_WALL_LEFT... of gembem/grain.h): a contact's j = -1 - wall.
WALLS = ("left", "right", "bottom", "top")


# The public structs this module reads, mirrored field for field (gembem/gem.h, run.h, status.h).
class _Error(ctypes.Structure):
    _fields_ = [("code", ctypes.c_int), ("msg", ctypes.c_char * 1024)]


class _Grain(ctypes.Structure):
    _fields_ = [(n, ctypes.c_double) for n in ("x", "y", "r", "rot")]


class _Box(ctypes.Structure):
    _fields_ = [(n, ctypes.c_double) for n in ("left", "right", "bottom", "top")]


class _Work(ctypes.Structure):
    _fields_ = [(n, ctypes.c_long) for n in ("trials", "factorisations", "sweeps")]


class _Report(ctypes.Structure):
    _fields_ = ([(n, ctypes.c_int) for n in ("stage", "step", "total_steps")]
                + [(n, ctypes.c_double) for n in ("e1", "e2", "ev", "s1", "s2", "stress_ratio")]
                + [("iterations", ctypes.c_long), ("substeps", ctypes.c_int), ("work", _Work),
                   ("cut_by", ctypes.c_int), ("max_fixing_force", ctypes.c_double), ("seconds", ctypes.c_double),
                   ("n_contacts", ctypes.c_int)]
                + [(n, ctypes.c_double) for n in ("width", "height", "force_scale", "accuracy", "wall_residual",
                                                  "max_particle_force", "coulomb_excess", "mean_normal_force",
                                                  "coordination")]
                + [("rattlers", ctypes.c_int)])


class _Place(ctypes.Structure):
    _fields_ = [(n, ctypes.c_int) for n in ("step", "stage", "stage_step", "stage_steps", "total_steps", "n_stages")]


# gb_contact as numpy records, so that gb_sim_contacts fills an array directly.
_CONTACT = np.dtype([("i", np.int32), ("j", np.int32)] + [(n, np.float64) for n in
                    ("nx", "ny", "overlap", "pn", "pt", "dissipation", "mr")], align=True)
_GRAIN = np.dtype([(n, np.float64) for n in ("x", "y", "r", "rotation")])

_P = ctypes.c_void_p
_ERR = ctypes.POINTER(_Error)
# name: (restype, argtypes); a gb_status is an int
_SIGNATURES = {
    "gb_version": (ctypes.c_char_p, []),
    "gb_status_name": (ctypes.c_char_p, [ctypes.c_int]),
    "gb_solve_stop_name": (ctypes.c_char_p, [ctypes.c_int]),
    "gb_scene_sizeof": (ctypes.c_size_t, []),
    "gb_scene_load": (ctypes.c_int, [ctypes.c_char_p, _P, _ERR]),
    "gb_scene_load_text": (ctypes.c_int, [ctypes.c_char_p, ctypes.c_size_t, ctypes.c_char_p, _P, _ERR]),
    "gb_scene_free": (None, [_P]),
    "gb_sim_create": (ctypes.c_int, [_P, ctypes.POINTER(_P), _ERR]),
    "gb_sim_free": (None, [_P]),
    "gb_run_create": (ctypes.c_int, [_P, ctypes.POINTER(_P), _ERR]),
    "gb_run_free": (None, [_P]),
    "gb_run_advance": (ctypes.c_int, [_P, _P, ctypes.POINTER(_Report), _ERR]),
    "gb_run_finished": (ctypes.c_int, [_P]),
    "gb_run_where": (_Place, [_P]),
    "gb_sim_n_grains": (ctypes.c_int, [_P]),
    "gb_sim_grains": (None, [_P, _P]),
    "gb_sim_contacts": (ctypes.c_int, [_P, _P, ctypes.c_int]),
    "gb_contacts_sliding": (None, [_P, _P, ctypes.c_int, _P]),
    "gb_sim_box": (_Box, [_P]),
    "gb_sim_wall_forces": (None, [_P, _P]),
    "gb_sim_host_dofs": (ctypes.c_int, [_P]),
    "gb_sim_host_cavity": (None, [_P, _P, _P, _P]),
    "gb_sim_host_group_force": (ctypes.c_int, [_P, ctypes.c_char_p, _P, _P, _ERR]),
    "gb_sim_elastic_energy": (ctypes.c_double, [_P]),
    "gb_state_write": (ctypes.c_int, [ctypes.c_char_p, _P, _ERR]),
}

_lib = None


def find_library(library=None):
    """The path of libgembem: the argument, else $GEMBEM_LIBRARY, else the one installed with this
    package, else this checkout's build tree. A path given that is not a file is an error."""
    for given, what in ((library, "the library argument"), (os.environ.get("GEMBEM_LIBRARY"), "$GEMBEM_LIBRARY")):
        if given:
            if not os.path.isfile(given):
                raise FileNotFoundError(f"{what} is '{given}': not a file")
            return os.fspath(given)
    for candidate in _INSTALLED, _BUILD_TREE:
        if candidate and os.path.isfile(candidate):
            return candidate
    raise FileNotFoundError(f"no gembem library: expected the library argument, $GEMBEM_LIBRARY or "
                            f"{_INSTALLED or _BUILD_TREE}")


def load_library(library=None):
    """libgembem loaded (once per process: a later call returns the first), its functions typed."""
    global _lib
    if _lib is None:
        lib = ctypes.CDLL(find_library(library))
        for name, (restype, argtypes) in _SIGNATURES.items():
            f = getattr(lib, name)
            f.restype, f.argtypes = restype, argtypes
        _lib = lib
    return _lib


def version():
    """The library's version (gb_version)."""
    return load_library().gb_version().decode()


def _check(lib, status, err, call):
    """Raises the exception of a gb_status that is not GB_OK, with the library's message."""
    if status:
        name = lib.gb_status_name(status).decode()
        raise error_for(status, err.msg.decode(errors="replace"), call, what=f"status {name}")


def _ptr(a):
    return a.ctypes.data_as(ctypes.c_void_p)


@dataclass(frozen=True)
class StepReport:
    """A load step's report (gb_step_report, gembem/gem.h; steps.csv has the same numbers): step 0
    is the initial state, stage -1 there. Stresses and strains compression positive, 1 vertical;
    cut_by: why the first attempt that was cut back stopped ("converged" if none was)."""
    stage: int
    step: int
    total_steps: int
    e1: float
    e2: float
    ev: float
    s1: float
    s2: float
    stress_ratio: float
    iterations: int
    substeps: int
    trials: int
    factorisations: int
    sweeps: int
    cut_by: str
    max_fixing_force: float
    seconds: float
    n_contacts: int
    width: float
    height: float
    force_scale: float
    accuracy: float
    wall_residual: float
    max_particle_force: float
    coulomb_excess: float
    mean_normal_force: float
    coordination: float
    rattlers: int


class Simulation:
    """A scene's simulation in this process. scene: the path of a scene file, or a gembem.Scene
    (given to the library as YAML text, read as a file named `name`, from whose directory its
    relative file names are read; Scene.load makes them absolute). The simulation starts before
    step 0; ``close()`` (or a ``with`` block, or the collector) frees it."""

    def __init__(self, scene, *, name=None, library=None):
        self._lib = lib = load_library(library)
        self._scene_room = ctypes.create_string_buffer(lib.gb_scene_sizeof())
        self._scene = ctypes.c_void_p(ctypes.addressof(self._scene_room))
        self._sim = ctypes.c_void_p()
        self._run = ctypes.c_void_p()
        err = _Error()
        if isinstance(scene, (str, os.PathLike)):
            self.path = os.fspath(scene)
            _check(lib, lib.gb_scene_load(self.path.encode(), self._scene, ctypes.byref(err)), err,
                   ["gb_scene_load", self.path])
        else:
            self.path = name or os.path.join(os.getcwd(), "scene.yaml")
            text = scene.to_yaml().encode()
            _check(lib, lib.gb_scene_load_text(text, len(text), self.path.encode(), self._scene, ctypes.byref(err)),
                   err, ["gb_scene_load_text", self.path])
        made = "gb_sim_create"
        status = lib.gb_sim_create(self._scene, ctypes.byref(self._sim), ctypes.byref(err))
        if not status:
            made = "gb_run_create"
            status = lib.gb_run_create(self._sim, ctypes.byref(self._run), ctypes.byref(err))
        if status:
            self.close()
            _check(lib, status, err, [made, self.path])
        self.report = None  # the last step's StepReport
        self._reports = []

    def close(self):
        """Frees the simulation and its scene (then every other call is an error)."""
        if self._run:
            self._lib.gb_run_free(self._run)
            self._run = ctypes.c_void_p()
        if self._sim:
            self._lib.gb_sim_free(self._sim)
            self._sim = ctypes.c_void_p()
        if self._scene is not None:
            self._lib.gb_scene_free(self._scene)
            self._scene = None

    def __del__(self):
        if getattr(self, "_lib", None) is not None:
            self.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def _handle(self):
        if not self._sim:
            raise ValueError(f"{self.path}: the simulation is closed")
        return self._sim

    # Stepping
    def step(self):
        """Takes the next step (the first call: step 0, the initial state) and returns its
        StepReport. A step that fails raises (ConvergenceError, ...) and leaves the state of the
        last completed step; past the last step: SceneError."""
        rep, err = _Report(), _Error()
        self._handle()
        _check(self._lib, self._lib.gb_run_advance(self._run, None, ctypes.byref(rep), ctypes.byref(err)),
               err, ["gb_run_advance", self.path])
        fields = {n: getattr(rep, n) for n, _ in _Report._fields_ if n not in ("work", "cut_by")}
        fields.update(trials=rep.work.trials, factorisations=rep.work.factorisations, sweeps=rep.work.sweeps,
                      cut_by=self._lib.gb_solve_stop_name(rep.cut_by).decode())
        self.report = StepReport(**fields)
        self._reports.append(self.report)
        return self.report

    @property
    def steps(self):
        """The steps taken so far as steps.csv would hold them (gembem.Run's steps): a Table of
        the columns the reports give, by steps.csv's names (stage 1-based there, 0 for step 0;
        contacts, e1_minus_e2), so that gembem.figures.stress_strain draws a Simulation."""
        rows = self._reports
        cols = {"step": [r.step for r in rows], "stage": [r.stage + 1 for r in rows],
                "e1_minus_e2": [r.e1 - r.e2 for r in rows], "contacts": [r.n_contacts for r in rows]}
        for name in ("e1", "e2", "ev", "s1", "s2", "stress_ratio", "iterations", "max_fixing_force", "seconds",
                     "width", "height", "substeps", "trials", "factorisations", "sweeps", "force_scale", "accuracy",
                     "coulomb_excess", "mean_normal_force", "coordination", "rattlers"):
            cols[name] = [getattr(r, name) for r in rows]
        return Table({k: np.array(v) for k, v in cols.items()})

    @property
    def finished(self):
        """Whether every step of the loading program is taken."""
        self._handle()
        return bool(self._lib.gb_run_finished(self._run))

    @property
    def place(self):
        """Where the program stands: a dict of the last step taken (-1: none yet; 0: the initial
        state), its stage (0-based, -1 for step 0) and stage_step (1-based) of stage_steps, and
        the program's total_steps and n_stages."""
        self._handle()
        p = self._lib.gb_run_where(self._run)
        return {n: getattr(p, n) for n, _ in _Place._fields_}

    def run_stage(self):
        """Takes the steps up to the end of the stage of the next step (step 0 first if not taken)
        and returns their reports."""
        reports = [self.step()] if self.place["step"] < 0 else []
        while not self.finished:
            reports.append(self.step())
            p = self.place
            if p["stage_step"] == p["stage_steps"]:
                break
        return reports

    def run(self):
        """Takes every step left (step 0 first if not taken) and returns their reports."""
        reports = [self.step()] if self.place["step"] < 0 else []
        while not self.finished:
            reports.append(self.step())
        return reports

    # Reading
    @property
    def grains(self):
        """The grains as the scene numbers them: a Table of x, y, r, rotation (radians)."""
        g = np.empty(self._lib.gb_sim_n_grains(self._handle()), dtype=_GRAIN)
        self._lib.gb_sim_grains(self._sim, _ptr(g))
        return Table({n: g[n].copy() for n in _GRAIN.names})

    @property
    def contacts(self):
        """The force-carrying contacts (i < j between grains, sorted): a Table of i, j (j < 0: the
        wall -1 - j of WALLS, or a host's boundary particle), pn, pt (K section 2.2), sliding
        (at the Coulomb limit, as the run's measures count them), nx, ny (the normal from i to j),
        overlap, dissipation (in the last step) and mr (the rolling moment on i)."""
        n = self._lib.gb_sim_contacts(self._handle(), None, 0)
        c = np.empty(n, dtype=_CONTACT)
        self._lib.gb_sim_contacts(self._sim, _ptr(c), n)
        sliding = np.zeros(n, dtype=np.intc)
        self._lib.gb_contacts_sliding(self._sim, _ptr(c), n, _ptr(sliding))
        cols = {"i": c["i"].astype(np.int64), "j": c["j"].astype(np.int64), "pn": c["pn"].copy(),
                "pt": c["pt"].copy(), "sliding": sliding.astype(bool)}
        cols.update({n: c[n].copy() for n in ("nx", "ny", "overlap", "dissipation", "mr")})
        return Table(cols)

    @property
    def walls(self):
        """The four walls in WALLS order: a Table of wall (name), position (where its face is: x
        of left and right, y of bottom and top) and force (the grains' normal force on it,
        compression positive; zero with a host)."""
        b = self._lib.gb_sim_box(self._handle())
        force = np.zeros(len(WALLS))
        self._lib.gb_sim_wall_forces(self._sim, _ptr(force))
        return Table({"wall": np.array(WALLS), "position": np.array([getattr(b, w) for w in WALLS]), "force": force})

    @property
    def elastic_energy(self):
        """The contact springs' elastic energy (K 22)."""
        return self._lib.gb_sim_elastic_energy(self._handle())

    @property
    def host(self):
        """A hybrid scene's cavity, per cavity element in the mesh's order: a Table of its
        displacement ux, uy, the host's force on it fx, fy (K u + f0: what the grains must put
        on the element) and the boundary particle's fixing force fix_x, fix_y (zero at
        equilibrium to the accuracy); None without a host."""
        m = self._lib.gb_sim_host_dofs(self._handle())
        if not m:
            return None
        u, f, fix = np.empty(m), np.empty(m), np.empty(m)
        self._lib.gb_sim_host_cavity(self._sim, _ptr(u), _ptr(f), _ptr(fix))
        return Table({"ux": u[0::2], "uy": u[1::2], "fx": f[0::2], "fy": f[1::2], "fix_x": fix[0::2],
                      "fix_y": fix[1::2]})

    def host_group(self, group):
        """A host's boundary group: its total force (what the outside puts on the body) and its
        mean displacement, each a numpy array (x, y)."""
        force, disp, err = np.empty(2), np.empty(2), _Error()
        _check(self._lib, self._lib.gb_sim_host_group_force(self._handle(), group.encode(), _ptr(force), _ptr(disp),
                                                            ctypes.byref(err)),
               err, ["gb_sim_host_group_force", group])
        return force, disp

    # Writing
    def write_state(self, directory):
        """Writes the state files (state.yaml, state_grains.csv, state_contacts.csv and a host's
        state_host.csv) into directory (created), as a run directory holds them: a scene starts
        from it with `initial_state:`, gembem.read_state reads it. Returns the directory."""
        directory = os.fspath(directory)
        os.makedirs(directory, exist_ok=True)
        err = _Error()
        _check(self._lib, self._lib.gb_state_write(directory.encode(), self._handle(), ctypes.byref(err)), err,
               ["gb_state_write", directory])
        return directory

    def __repr__(self):
        if not self._sim:
            return f"Simulation({self.path!r}, closed)"
        p = self.place
        return f"Simulation({self.path!r}: step {p['step']} of {p['total_steps']})"
