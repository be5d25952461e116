"""A biaxial run directory of gembem read with the gembem package (python/): the shear stage's
start and peak, and its strains counted from the start of the shear, as numpy arrays.

steps.csv and micromechanics.csv have one row per step, step 0 first, so a step is a row index.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import gembem  # noqa: E402


class Biaxial:
    """gembem.Run of a biaxial test (``run``, ``steps``, ``micro``), with per step (arrays indexed
    by step): ``ratio`` s1/s2 (nan where s2 <= 0), ``gamma`` e1 - e2 [%] and ``ev`` [%] since the
    start of the shear (0 before it); ``shear_start`` the step the last stage starts from, ``shear``
    that step and the last stage's steps, ``peak_step`` the largest s1/s2 of the last stage."""

    def __init__(self, rundir):
        self.run = gembem.Run(rundir)
        self.steps, self.micro = self.run.steps, self.run.micromechanics
        s = self.steps
        if not np.array_equal(s["step"], np.arange(s.nrows)):
            raise ValueError(f"{s.path}: expected one row per step from step 0")
        last = np.flatnonzero(s["stage"] == s["stage"].max())
        self.shear_start = int(s["step"][last[0]]) - 1   # the state the shear starts from
        self.shear = np.r_[self.shear_start, last]
        s2 = np.asarray(s["s2"], dtype=float)
        self.ratio = np.divide(s["s1"], s2, out=np.full(s.nrows, np.nan), where=s2 > 0)
        after = s["step"] > self.shear_start
        self.gamma = np.where(after, 100 * s["e1_minus_e2"], 0.0)
        self.ev = np.where(after, 100 * s["ev"], 0.0)   # the shear stage resets the strain's reference
        self.peak_step = int(last[np.argmax(self.ratio[last])])

    def balance_from_shear_start(self, step):
        """(W - D - dE)/W counted from the start of the shear, and W."""
        d = lambda k: float(self.micro[k][step] - self.micro[k][self.shear_start])
        w = d("work")
        return ((w - d("dissipation") - d("elastic_energy")) / w if w else 0.0), w
