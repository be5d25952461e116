"""Scenes built from Python objects and written as YAML (PyYAML's safe dumper, no templating).

The C reader is the authority on what a scene may hold: nothing here checks keys, types or
values. A scene is its top-level sections as plain dicts and lists (docs/scene.md), numpy
arrays and numbers welcome; a bad scene is refused by `gembem run` with file:line:column, which
gembem.runner raises as gembem.errors.SceneError.
"""
import copy
import dataclasses
import os
import pathlib
from dataclasses import dataclass, field

import numpy as np

from .rundir import Run
from .state import State
from .yamlfile import dump_yaml, read_yaml

# The scene keys that name files, which gembem resolves relative to the scene file's directory
# (gb_yaml_relative_path in src/scene/). Scene.load makes them absolute, so that a scene loaded
# from one directory and written to another still names the same files.
PATH_KEYS = (("grains", "file"), ("grains", "contacts"), ("host", "mesh"), ("initial_state",))


@dataclass
class Scene:
    """A gembem scene. Each field is the top-level section of the same name, written when not
    None; ``extra`` holds any other top-level key, written as given.

    ``grains`` may be an N x 3 or N x 4 array (x, y, r[, rotation]), written inline or, with
    ``write(..., grains_file=NAME)``, as a CSV file beside the scene; or the section's own map
    (``{"file": ...}``, ``{"list": ...}``). ``initial_state`` may be a Run or a State (a
    preparation run whose final state the scene starts from). A pathlib.Path anywhere is written
    as an absolute path; a str as given (gembem reads a relative one from the scene's directory).
    """
    units: dict = None
    materials: dict = None
    grains: object = None
    box: dict = None
    host: dict = None
    initial_state: object = None
    body_force: dict = None
    solver: dict = None
    loading: list = None
    output: dict = None
    extra: dict = field(default_factory=dict)
    version: int = 1

    @classmethod
    def load(cls, path):
        """A scene read from a YAML file (e.g. to vary a validated one); its file names made absolute."""
        doc = read_yaml(path)
        if not isinstance(doc, dict):
            raise ValueError(f"{path}: expected a map of scene sections, found {type(doc).__name__}")
        base = pathlib.Path(path).resolve().parent
        for keys in PATH_KEYS:
            parent = doc
            for k in keys[:-1]:
                parent = parent.get(k) if isinstance(parent, dict) else None
            if isinstance(parent, dict) and isinstance(parent.get(keys[-1]), str):
                parent[keys[-1]] = base / parent[keys[-1]]
        names = {f.name for f in dataclasses.fields(cls)} - {"extra", "version"}
        kwargs = {k: doc.pop(k) for k in list(doc) if k in names}
        version = doc.pop("gembem", 1)
        return cls(**kwargs, extra=doc, version=version)

    def __repr__(self):
        """The sections it has, with the sizes of the long ones: a scene's grains can be thousands."""
        parts = []
        for name in [f.name for f in dataclasses.fields(self) if f.name not in ("extra", "version")] + list(self.extra):
            v = self.extra[name] if name in self.extra else getattr(self, name)
            if v is None:
                continue
            if name == "grains":
                listed = v.get("list") if isinstance(v, dict) else v
                if isinstance(v, dict) and "file" in v:
                    name += f" (file {os.path.basename(os.fspath(v['file']))})"
                elif listed is not None and not isinstance(listed, (str, dict)):
                    name += f" ({len(listed)} grains)"
            elif name == "loading" and isinstance(v, list):
                name += f" ({len(v)} stage{'s' if len(v) != 1 else ''})"
            elif name == "initial_state":
                name += f" ({getattr(v, 'path', v)})"
            parts.append(name)
        return f"Scene({', '.join(parts)})"

    def with_value(self, dotted, value):
        """A copy with one value replaced, e.g. ``with_value("materials.grain_grain.friction_deg", 25)``
        or ``with_value("loading.1.shear_mean_stress.steps", 50)`` (list items by index); maps on
        the way that do not exist are created."""
        keys = dotted.split(".")
        new = copy.deepcopy(self)
        if keys[0] not in {f.name for f in dataclasses.fields(self)}:
            new.extra = _set(new.extra, keys, value)
        else:
            setattr(new, keys[0], _set(getattr(new, keys[0]), keys[1:], value) if len(keys) > 1 else value)
        return new

    def value(self, dotted):
        """The value at a dotted key (as with_value names it); KeyError naming the first key on the
        way that the scene does not have (a section left None counts as absent)."""
        keys = dotted.split(".")
        node = getattr(self, keys[0]) if keys[0] in _SECTIONS else self.extra.get(keys[0])
        if node is None and (keys[0] in _SECTIONS or keys[0] not in self.extra):
            raise KeyError(keys[0])
        for i, k in enumerate(keys[1:], 1):
            node = _child(node, k, ".".join(keys[:i + 1]))
        return node

    def has(self, dotted):
        """Whether the scene has a value at the dotted key."""
        try:
            self.value(dotted)
        except KeyError:
            return False
        return True

    def without(self, dotted):
        """A copy with the value at a dotted key removed (a list item by index: the item, the others
        moving up); KeyError naming the first missing key on the way if there is none."""
        self.value(dotted)
        keys = dotted.split(".")
        new = copy.deepcopy(self)
        if len(keys) == 1:
            if keys[0] in _SECTIONS:
                setattr(new, keys[0], None)
            else:
                del new.extra[keys[0]]
            return new
        parent = new.value(".".join(keys[:-1]))
        del parent[int(keys[-1]) if isinstance(parent, list) else keys[-1]]
        return new

    def to_dict(self, grains_file=None):
        """The scene as plain Python objects, in the order docs/scene.md lists the sections.

        grains_file: the name the grains' CSV will have (see write); None writes them inline.
        """
        out = {"gembem": self.version}
        for f in dataclasses.fields(self):
            value = getattr(self, f.name)
            if f.name in ("extra", "version") or value is None:
                continue
            if f.name == "grains" and not isinstance(value, dict):
                value = {"file": grains_file} if grains_file else {"list": np.asarray(value, dtype=float)}
            if f.name == "initial_state" and isinstance(value, (Run, State)):
                value = pathlib.Path(value.file("state.yaml") if isinstance(value, Run) else value.path)
            out[f.name] = value
        out.update(self.extra)
        return _plain(out)

    def to_yaml(self, grains_file=None, comment=None):
        """The scene as YAML text: short maps and lists on one line, floats exact (shortest repr).
        comment: what the scene is, written first as '#' lines (one per line of the text)."""
        lines = (comment.splitlines() if comment else []) + ["a gembem scene written by the gembem Python package"]
        return "".join(f"# {line}".rstrip() + "\n" for line in lines) + dump_yaml(self.to_dict(grains_file), short=100)

    def write(self, path, grains_file=None, comment=None):
        """Writes the scene to PATH (its directory created); returns the path.

        grains_file: write an array of grains to this CSV file (relative to the scene's directory,
        columns x, y, r[, rotation]) instead of inline: for large packings. comment: see to_yaml.
        """
        path = os.fspath(path)
        os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
        if grains_file and not isinstance(self.grains, dict):
            write_grains_csv(os.path.join(os.path.dirname(os.path.abspath(path)), grains_file), self.grains)
        text = self.to_yaml(grains_file, comment)
        with open(path, "w") as f:
            f.write(text)
        return path


def write_grains_csv(path, grains):
    """Grains (N x 3 or N x 4: x, y, r[, rotation]) as the CSV gembem reads, floats exact."""
    g = np.asarray(grains, dtype=float)
    if g.ndim != 2 or g.shape[1] not in (3, 4):
        raise ValueError(f"{path}: grains of shape {g.shape}, expected N x 3 (x, y, r) or N x 4 (x, y, r, rotation)")
    with open(path, "w") as f:
        f.write("x,y,r,rotation\n" if g.shape[1] == 4 else "x,y,r\n")
        for row in g:
            f.write(",".join(repr(float(v)) for v in row) + "\n")


_SECTIONS = {f.name for f in dataclasses.fields(Scene)} - {"extra", "version"}


def _child(node, key, where):
    """node[key] (a list's item by index); KeyError(where) if node has no such key or item."""
    if isinstance(node, dict) and key in node:
        return node[key]
    if isinstance(node, list) and key.lstrip("-").isdigit() and -len(node) <= int(key) < len(node):
        return node[int(key)]
    raise KeyError(where)


def _set(node, keys, value):
    """node with node[k0][k1]... = value (node copied by the caller); creates missing maps."""
    if not keys:
        return value
    if node is None:
        node = {}
    k = int(keys[0]) if isinstance(node, list) else keys[0]
    node[k] = _set(node[k] if isinstance(node, list) else node.get(k), keys[1:], value)
    return node


def _plain(obj):
    """Plain Python objects that yaml.safe_dump writes: numpy values, tuples, Paths, dataclasses converted."""
    if isinstance(obj, dict):
        return {str(k): _plain(v) for k, v in obj.items()}
    if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        return _plain(dataclasses.asdict(obj))
    if isinstance(obj, np.ndarray):
        return _plain(obj.tolist())
    if isinstance(obj, (list, tuple)):
        return [_plain(v) for v in obj]
    if isinstance(obj, np.generic):
        return obj.item()
    if isinstance(obj, pathlib.PurePath):
        return str(pathlib.Path(obj).resolve())
    return obj
