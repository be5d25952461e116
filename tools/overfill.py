#!/usr/bin/python3
"""Overfills a packing's box: shrinks the disc centres and the box about the box's centre until the
porosity (1 - disc area / box area) is the target, so that neighbours overlap by a few per cent.
Relaxed with the walls fixed, such a packing stays jammed (tools/bench_gem.sh's preparation).

usage: overfill.py GRAINS.csv BOX.yaml POROSITY OUT.csv    (prints the new box line)
"""
import csv
import math
import re
import sys


def main():
    grains, boxfile, target, out = sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4]
    g = list(csv.DictReader(open(grains)))
    m = re.search(r"left: ([-0-9.e+]+), right: ([-0-9.e+]+), bottom: ([-0-9.e+]+), top: ([-0-9.e+]+)",
                  open(boxfile).read())
    left, right, bottom, top = map(float, m.groups())
    area = sum(math.pi * float(q["r"]) ** 2 for q in g)
    porosity = 1 - area / ((right - left) * (top - bottom))
    if not 0 < target < porosity:
        sys.exit(f"overfill.py: the packing's porosity is {porosity:.4f}; expected a target below it")
    f = math.sqrt((1 - porosity) / (1 - target))
    cx, cy = (left + right) / 2, (bottom + top) / 2
    with open(out, "w") as o:
        o.write("x,y,r\n")
        for q in g:
            o.write(f"{cx + f * (float(q['x']) - cx):.12g},{cy + f * (float(q['y']) - cy):.12g},{q['r']}\n")
    print(f"box: {{left: {cx - f * (cx - left):.12g}, right: {cx + f * (right - cx):.12g}, "
          f"bottom: {cy - f * (cy - bottom):.12g}, top: {cy + f * (top - cy):.12g}}}")


if __name__ == "__main__":
    main()
