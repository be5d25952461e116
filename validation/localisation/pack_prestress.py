#!/usr/bin/python3
"""How much of a study packing's pre-stress is the packing's accuracy: the case's pack scene
(study.py pack_scene, as the workflow packs it) packed again with other values of its absolute
accuracy, the same seed; a table of what each packing holds (pack_info.yaml).

The study's packings are grown frictionless to a solid fraction (0.82 of the usable disc); if that
is below jamming, fully relaxed grains press on nothing, and the contact forces a packing keeps are
what FIRE left when it stopped (at 4 times the accuracy, docs/packing.md): its mean stress then
falls with the accuracy. README "Odd things" quotes this table.

Usage: validation/localisation/pack_prestress.py CASE DIR [BUILD_DIR] [--accuracy A ...]
   e.g. pack_prestress.py k0.01_p100_nr/s02 runs/prestress         (1000 grains, the statistics)
        pack_prestress.py scale/k0.01_p100_nr/s02 runs/prestress   (1e4 grains, the study at scale)
Writes DIR/<accuracy>/pack.yaml and the packing in DIR/<accuracy>/pack/; prints the table."""
import argparse
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "python"))
sys.path.insert(0, HERE)
from gembem.yamlfile import read_yaml  # noqa: E402
import study  # noqa: E402

MESH = os.path.join(ROOT, "meshes", "square_cavity_sides.geo")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("case")
    ap.add_argument("dir")
    ap.add_argument("build", nargs="?", default=os.path.join(ROOT, "build"))
    ap.add_argument("--accuracy", type=float, nargs="+", help="absolute accuracies [kgf] (default: the "
                    "study's 5e-5 kn, then 1/5, 1/25 and 1/500 of it)")
    a = ap.parse_args()
    scene, comment = study.pack_scene(a.case, MESH)
    base = float(scene.solver["accuracy"])
    print(f"{a.case}: the study packs at {base:g} (kn {scene.materials['grain_grain']['kn']:g})")
    print("| accuracy [kgf] | mean stress [kgf/cm] | coordination | rattlers | largest overlap / smaller radius | largest fixing force [kgf] |")
    print("|---|---|---|---|---|---|")
    for acc in a.accuracy or [base, base / 5, base / 25, base / 500]:
        d = os.path.join(a.dir, f"{acc:g}")
        os.makedirs(d, exist_ok=True)
        scene.solver = dict(scene.solver, accuracy=acc)
        scene.write(os.path.join(d, "pack.yaml"), comment=comment + f"\nThe accuracy set to {acc:g} (pack_prestress.py).")
        subprocess.run([os.path.join(a.build, "gembem"), "pack", os.path.join(d, "pack.yaml"), "-o",
                        os.path.join(d, "pack"), "--overwrite", "--quiet"], check=True)
        info = read_yaml(os.path.join(d, "pack", "pack_info.yaml"))
        print(f"| {acc:g} | {info['mean_stress']:.3g} | {info['coordination']:.2f} | {info['rattlers']} | "
              f"{info['largest_overlap']:.2g} | {info['max_fixing_force']:.2g} |")


if __name__ == "__main__":
    main()
