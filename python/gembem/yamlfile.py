"""YAML in and out through PyYAML (Debian's python3-yaml), with numbers read as gembem reads them.

PyYAML follows YAML 1.1, where `1e8` and `1.5e5` are strings (its floats need a dot and a signed
exponent); gembem's reader (libfyaml) takes them as numbers, as YAML 1.2 does. The loader here
resolves them as floats too, so that a scene or state read from Python holds the numbers gembem
sees.
"""
import re

import yaml


class Loader(yaml.SafeLoader):
    """PyYAML's safe loader with YAML 1.2's floats (1e8, 1.5e5, .5)."""


Loader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(r"^[-+]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)[eE][-+]?[0-9]+$"),
    list("-+0123456789."))


def read_yaml(path):
    """A YAML file as Python objects; an error names the file."""
    try:
        with open(path) as f:
            return yaml.load(f, Loader=Loader)
    except yaml.YAMLError as e:
        raise ValueError(f"{path}: not YAML: {e}") from None


def parse_yaml(text):
    """YAML text (e.g. a value given on a command line, `{kn: 1e3, kt: 500}`) as Python objects,
    numbers as read_yaml reads them."""
    return yaml.load(text, Loader=Loader)


def dump_yaml(data, block=False, short=0):
    """YAML text of plain Python objects, maps in their order, maps and lists of scalars alone on
    one line (block: one line per key); short: also any map or list whose one line would be at
    most this long, but the top level's and a list's maps (`- relax: {steps: 1}`); floats written
    by repr, the shortest text that reads back to the same double."""
    if short and not block:
        dumper = type("Dumper", (_ShortDumper,), {"root": data, "short": short})
        return yaml.dump(data, Dumper=dumper, sort_keys=False, width=short + 20)
    return yaml.safe_dump(data, sort_keys=False, default_flow_style=False if block else None, width=100)


def _flow_length(obj, limit):
    """About the length of obj written on one line, or more than limit once it exceeds limit."""
    if isinstance(obj, dict):
        n = 2
        for k, v in obj.items():
            n += len(str(k)) + 4 + _flow_length(v, limit - n)
            if n > limit:
                break
        return n
    if isinstance(obj, (list, tuple)):
        n = 2
        for v in obj:
            n += 2 + _flow_length(v, limit - n)
            if n > limit:
                break
        return n
    if isinstance(obj, str):
        return len(obj) + 2
    return len(repr(obj)) + 2


class _ShortDumper(yaml.SafeDumper):
    """dump_yaml(short=...): short collections on one line."""
    root = None
    short = 0

    def _flow(self, data, children):
        if data is self.root or id(data) in self._block:
            return False
        if not any(isinstance(v, (dict, list, tuple)) for v in children):
            return True
        return _flow_length(data, self.short) <= self.short

    def represent_short_dict(self, data):
        self._block = getattr(self, "_block", set())
        return self.represent_mapping("tag:yaml.org,2002:map", data, flow_style=self._flow(data, data.values()))

    def represent_short_list(self, data):
        self._block = getattr(self, "_block", set())
        flow = self._flow(data, data)
        if not flow:
            self._block.update(id(v) for v in data if isinstance(v, dict))
        return self.represent_sequence("tag:yaml.org,2002:seq", data, flow_style=flow)


_ShortDumper.add_representer(dict, _ShortDumper.represent_short_dict)
_ShortDumper.add_representer(list, _ShortDumper.represent_short_list)
