"""The scenes of validation C (the 27-grain cavity packing) as gembem.Scene objects: as placed
(scene.yaml) and confined (every radius x 1.15, so that the packing presses on the host), with a
chosen solver and accuracy. Used by regenerate.py and tools/speed_vs_error.py.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
import gembem  # noqa: E402

CASES = ("placed", "confined")
CONFINE = 1.15  # the confined case's radius factor


def cavity_scene(case="placed", linear=None, accuracy=None, method=None):
    """scene.yaml (its mesh named by an absolute path), confined if case is 'confined': every
    radius x 1.15 (to 4 decimals: 0.575 and 0.345 cm) and grains.max_overlap 0.7, since G and H
    then overlap by 0.61 of the small radius, more than the admission's default 0.5. linear,
    accuracy [kgf], method: the solver's keys when given."""
    if case not in CASES:
        raise ValueError(f"cavity case '{case}': expected one of {', '.join(CASES)}")
    s = gembem.Scene.load(os.path.join(HERE, "scene.yaml"))
    if case == "confined":
        grains = [[x, y, round(r * CONFINE, 4)] for x, y, r in s.grains["list"]]
        s = s.with_value("grains.list", grains).with_value("grains.max_overlap", 0.7)
    for key, value in (("linear", linear), ("accuracy", accuracy), ("method", method)):
        if value is not None:
            s = s.with_value(f"solver.{key}", value)
    return s
