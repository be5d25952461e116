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


def dump_yaml(data, block=False):
    """YAML text of plain Python objects, maps in their order, short maps and lists on one line
    (block: one line per key); floats written by repr, the shortest text that reads back to the
    same double."""
    return yaml.safe_dump(data, sort_keys=False, default_flow_style=False if block else None, width=100)
