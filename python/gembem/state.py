"""A state file (RUN/state.yaml, the final state of a run, which a scene can start from)."""
import os
from dataclasses import dataclass

from .table import Table, read_csv
from .yamlfile import read_yaml


@dataclass
class State:
    """The box, the grains (x, y, r, rotation), the contacts with their forces and, for a hybrid
    run, the host (its YAML section and per cavity element the particle's centre and
    displacement). ``yaml`` is the whole file as loaded, for what has no attribute here."""
    path: str
    box: dict
    grains: Table
    contacts: Table
    host: dict
    host_particles: Table
    yaml: dict

    def __repr__(self):
        b = self.box
        box = f", box x [{b['left']:.6g}, {b['right']:.6g}] y [{b['bottom']:.6g}, {b['top']:.6g}]" if b else ""
        host = f", host: {self.host_particles.nrows} boundary particles" if self.host_particles is not None else ""
        return f"State({self.path!r}: {self.grains.nrows} grains, {self.contacts.nrows} contacts{box}{host})"


def read_state(path):
    """Reads a state: the path of state.yaml, or of a run directory holding one.

    File names inside it are relative to the state file, as gembem resolves them.
    """
    path = os.fspath(path)
    if os.path.isdir(path):
        path = os.path.join(path, "state.yaml")
    doc = read_yaml(path)
    if not isinstance(doc, dict) or "gembem_state" not in doc:
        raise ValueError(f"{path}: expected a gembem state (a map with 'gembem_state'), as a run writes")
    base = os.path.dirname(path)
    files = doc["grains"]
    host = doc.get("host")
    particles = read_csv(os.path.join(base, host["particles"])) if host else None
    return State(path, doc.get("box"), read_csv(os.path.join(base, files["file"])),
                 read_csv(os.path.join(base, files["contacts"])), host, particles, doc)
