"""A run directory (what `gembem run SCENE -o RUN` leaves) or a packing directory (`gembem pack`)
as numpy arrays, file by file.

Every CSV goes through the one reader, gembem.table.read_csv; the per-step files are named
FOLDER/KIND_NNNNNN.csv (contacts/, fields/), VTK files go through gembem.vtk.
"""
import fcntl
import functools
import os
import re
import struct

from .state import read_state
from .table import read_csv
from .vtk import read_vtk
from .yamlfile import read_yaml

# Why a file may be missing: which scene key or scene kind writes it (see docs/run-directory.md).
_WHY = {
    "history.csv": "written with `solver: {history: true}`",
    "contacts": "written every `output.contacts_every` steps and at snapshot steps",
    "fields": "written every `output.measures_every` steps",
    "localisation.csv": "written unless `output: {localisation: false}`",
    "snapshots": "written at `output.snapshot_every` / `snapshot_steps`",
    "host": "written by hybrid scenes only, those with a `host:` section",
}


def _why(name):
    key = name.split("/")[0] if "/" in name else name
    if key.startswith("host_"):
        key = "host"
    return _WHY.get(key, "")


def read_lock(path):
    """A run directory's lock file (.lock) as a dict of its fields: pid, host, started, status."""
    with open(path) as f:
        return {k: v.strip() for k, v in (line.split(": ", 1) for line in f.read().splitlines()
                                          if ": " in line and not line.startswith("#"))}


def lock_state(run_dir):
    """(held, status) of RUN_DIR/.lock: whether a live process holds it (a test of the lock, which
    takes nothing: F_GETLK) and the status it last recorded ('' without a lock file)."""
    path = os.path.join(run_dir, ".lock")
    try:
        fd = os.open(path, os.O_RDONLY)
    except FileNotFoundError:
        return False, ""
    try:
        # struct flock: l_type, l_whence, l_start, l_len, l_pid (and its padding)
        query = struct.pack("hhqqi4x", fcntl.F_WRLCK, os.SEEK_SET, 0, 0, 0)
        held = struct.unpack("hhqqi4x", fcntl.fcntl(fd, fcntl.F_GETLK, query))[0] != fcntl.F_UNLCK
        text = os.pread(fd, 4096, 0).decode("utf-8", "replace")
    finally:
        os.close(fd)
    status = next((line.split(": ", 1)[1].strip() for line in text.splitlines()
                   if line.startswith("status: ")), "")
    return held, status


def _table(name, doc):
    """A Run attribute that reads NAME when first used."""
    def get(self):
        return self.table(name)
    get.__doc__ = f"{name}: {doc}"
    return functools.cached_property(get)


class _Directory:
    """What a run directory and a packing directory share: a scene copy and a final state."""
    kind, marker, writer = "", "", ""

    def __init__(self, path):
        self.path = os.fspath(path)
        if not os.path.isfile(os.path.join(self.path, self.marker)):
            other = next((c for c in (Run, Packing) if c is not type(self)
                          and os.path.isfile(os.path.join(self.path, c.marker))), None)
            hint = (f" but a {other.kind} ({other.marker}): gembem.{other.__name__} reads it" if other
                    else f"; expected the directory of `{self.writer}`")
            raise FileNotFoundError(f"{self.path}: not a {self.kind} (no {self.marker}){hint}")

    def file(self, name):
        """The path of a file of the directory; a missing one raises FileNotFoundError saying what writes it."""
        path = os.path.join(self.path, name)
        if not os.path.exists(path):
            why = _why(name)
            raise FileNotFoundError(f"{path}: no such file in the {self.kind}" + (f" ({why})" if why else ""))
        return path

    def table(self, name):
        """Any CSV file of the directory, by its path relative to it."""
        return read_csv(self.file(name))

    @functools.cached_property
    def state(self):
        """The final state (state.yaml and its CSV files)."""
        return read_state(self.file("state.yaml"))

    @functools.cached_property
    def scene(self):
        """The copy of the scene (scene.yaml), as loaded by yaml."""
        return read_yaml(self.file("scene.yaml"))


class Packing(_Directory):
    """What `gembem pack SCENE -o DIR` leaves: ``pack_info`` (pack_info.yaml as a dict: solid
    fraction, coordination, radius_scale, ...), ``state`` and ``scene``; ``grains()`` and
    ``contacts()`` are the state's, as a Run's final ones, so that the figures of a final state
    draw a packing too."""
    kind, marker, writer = "packing directory", "pack_info.yaml", "gembem pack SCENE -o DIR"

    def __repr__(self):
        return f"Packing({self.path!r})"

    @functools.cached_property
    def pack_info(self):
        """pack_info.yaml: how the packing was made and what it is."""
        return read_yaml(self.file("pack_info.yaml"))

    def grains(self, step=None):
        """The packed grains (the state's); a packing has no steps (step None)."""
        return self._final(step, self.state.grains)

    def contacts(self, step=None):
        """The packing's contacts (the state's); a packing has no steps (step None)."""
        return self._final(step, self.state.contacts)

    def _final(self, step, table):
        if step is not None:
            raise ValueError(f"{self.path}: a packing has its final state only, not step {step}")
        return table


def open_directory(path):
    """A Run or a Packing, whichever PATH is (run_info.yaml or pack_info.yaml)."""
    for kind in (Run, Packing):
        if os.path.isfile(os.path.join(os.fspath(path), kind.marker)):
            return kind(path)
    raise FileNotFoundError(f"{os.fspath(path)}: neither a run directory (run_info.yaml) nor a packing directory "
                            "(pack_info.yaml); expected the directory of `gembem run` or `gembem pack`")


class Run(_Directory):
    """The outputs of one run directory, read when first asked for (and then kept).

    Tables (gembem.table.Table: columns by name): ``steps``, ``history``, ``micromechanics``,
    ``localisation``, ``host_steps``, ``host_particles``, ``host_boundary``; any other CSV by its
    path in the directory with ``table(name)``. Per step: ``contacts(step)``, ``grains(step)``,
    ``rose(step)`` (contacts/), ``field(kind, step)`` (fields/: grains, sliding, host_wall,
    host_ring), and which steps have them: ``steps_of(folder, kind)``. The final state:
    ``state`` (gembem.state.State). YAML as dicts: ``scene``, ``run_info``, ``host_info``. VTK:
    ``host_field()``, ``snapshot(kind, step)``.
    """
    kind, marker, writer = "run directory", "run_info.yaml", "gembem run SCENE -o RUNDIR"

    def __repr__(self):
        return f"Run({self.path!r})"

    steps = _table("steps.csv", "one row per load step, step 0 the initial state")
    history = _table("history.csv", "one row per iteration that did not converge")
    micromechanics = _table("micromechanics.csv", "fabric, elastic energy, work, dissipation per step")
    localisation = _table("localisation.csv", "the per-step strain and localisation measures")
    host_steps = _table("host_steps.csv", "per step and boundary group: displacement and force")
    host_particles = _table("host_particles.csv", "the boundary particles at the end")
    host_boundary = _table("host_boundary.csv", "per boundary element at the end")

    @functools.cached_property
    def run_info(self):
        """run_info.yaml: version, command, status."""
        return read_yaml(self.file("run_info.yaml"))

    @functools.cached_property
    def host_info(self):
        """host_info.yaml: the condensed host stiffness's asymmetry and condition."""
        return read_yaml(self.file("host_info.yaml"))

    @property
    def status(self):
        """How the run stands (read afresh): run_info.yaml's status (completed, interrupted, not
        converged, i/o error, ...), but for a `running` there: `running` while a gembem process
        holds the directory's lock, else the status its lock file recorded (a disk too full to
        rewrite run_info.yaml) or `killed` (docs/run-directory.md, "The morning after")."""
        status = read_yaml(self.file("run_info.yaml")).get("status")
        if status != "running":
            return status
        held, recorded = lock_state(self.path)
        if held:
            return "running"
        return recorded if recorded and recorded != "running" else "killed"

    @property
    def holder(self):
        """Who holds (or last held) the run directory: the lock file's pid, host, started, status
        as a dict ({} without one), with `live` True while that process holds it."""
        path = os.path.join(self.path, ".lock")
        if not os.path.exists(path):
            return {}
        fields = read_lock(path)
        fields["live"] = lock_state(self.path)[0]
        return fields

    def step_file(self, folder, kind, step, ext="csv"):
        return self.file(f"{folder}/{kind}_{int(step):06d}.{ext}")

    def steps_of(self, folder, kind, ext="csv"):
        """The steps that have a FOLDER/KIND_NNNNNN file, sorted (e.g. steps_of("fields", "grains"))."""
        d = os.path.join(self.path, folder)
        pat = re.compile(rf"{re.escape(kind)}_(\d{{6}})\.{ext}$")
        names = os.listdir(d) if os.path.isdir(d) else []
        return sorted(int(m.group(1)) for m in map(pat.match, names) if m)

    def contacts(self, step=None):
        """Contacts at a step (contacts/contacts_NNNNNN.csv), or of the final state (step None)."""
        return self.state.contacts if step is None else read_csv(self.step_file("contacts", "contacts", step))

    def grains(self, step=None):
        """Grains at a step (contacts/grains_NNNNNN.csv), or of the final state (step None)."""
        return self.state.grains if step is None else read_csv(self.step_file("contacts", "grains", step))

    def rose(self, step):
        """Contact directions by 10-degree sector at a step (contacts/rose_NNNNNN.csv)."""
        return read_csv(self.step_file("contacts", "rose", step))

    def field(self, kind, step):
        """fields/KIND_NNNNNN.csv: kind grains, sliding, host_wall or host_ring."""
        return read_csv(self.step_file("fields", kind, step))

    def host_field(self):
        """host_field.vtu: the host's interior displacement and stress at the end (gembem.vtk.Mesh)."""
        return read_vtk(self.file("host_field.vtu"))

    def snapshot(self, kind, step):
        """snapshots/KIND_NNNNNN.vtp, kind grains or contacts (gembem.vtk.Mesh)."""
        return read_vtk(self.step_file("snapshots", kind, step, "vtp"))
