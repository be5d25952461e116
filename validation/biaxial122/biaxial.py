"""Reading a biaxial run directory of gembem: steps, micromechanics, contacts per step."""
import csv
import os


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


class Run:
    def __init__(self, rundir):
        self.dir = rundir
        self.steps = read_csv(os.path.join(rundir, "steps.csv"))
        self.micro = read_csv(os.path.join(rundir, "micromechanics.csv"))
        last_stage = max(int(r["stage"]) for r in self.steps)
        shear = [r for r in self.steps if int(r["stage"]) == last_stage]
        self.shear_start = int(shear[0]["step"]) - 1   # the state the shear starts from
        self.shear = [self.steps[self.shear_start]] + shear
        ratio = [self.principal_ratio(r) for r in shear]
        self.peak_step = int(shear[ratio.index(max(ratio))]["step"])

    @staticmethod
    def principal_ratio(row):
        s1, s2 = float(row["s1"]), float(row["s2"])
        return s1 / s2 if s2 > 0 else float("nan")

    def shear_strain(self, row):
        return 100 * float(row["e1_minus_e2"]) if int(row["step"]) > self.shear_start else 0.0

    def shear_ev(self, row):
        """Volumetric strain since the start of the shear [%] (the shear stage resets the reference)."""
        return 100 * float(row["ev"]) if int(row["step"]) > self.shear_start else 0.0

    def micro_at(self, step):
        return self.micro[step]

    def contacts(self, step):
        return read_csv(os.path.join(self.dir, "contacts", f"contacts_{step:06d}.csv"))

    def rose(self, step):
        return read_csv(os.path.join(self.dir, "contacts", f"rose_{step:06d}.csv"))

    def grains(self, step):
        return read_csv(os.path.join(self.dir, "contacts", f"grains_{step:06d}.csv"))

    def balance_from_shear_start(self, step):
        """(W - D - dE)/W counted from the start of the shear, and W."""
        a, b = self.micro[self.shear_start], self.micro[step]
        d = lambda k: float(b[k]) - float(a[k])
        w = d("work")
        return ((w - d("dissipation") - d("elastic_energy")) / w if w else 0.0), w
