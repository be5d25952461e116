#!/usr/bin/env bash
# Validation C: runs the cavity packing as placed (scene.yaml) and confined (every radius x 1.15,
# made from scene.yaml) with UMFPACK and with CHOLMOD, draws the figures and prints the table of
# README.md.   validation/cavity_packing/regenerate.sh [BUILD_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd); root=$(cd "$here/../.." && pwd)
gembem=$root/${1:-build}/gembem
runs=$root/runs/cavity_packing; mkdir -p "$runs"
/usr/bin/python3 - "$here/scene.yaml" "$runs/confined.yaml" <<'PY'
import re, sys
text = open(sys.argv[1]).read().replace("../../meshes/", sys.argv[1].rsplit("/", 3)[0] + "/meshes/")
text = re.sub(r"\[(-?[0-9.]+), (-?[0-9.]+), (0\.[35])\]",
              lambda m: f"[{m.group(1)}, {m.group(2)}, {float(m.group(3)) * 1.15:.4f}]", text)
# G and H then overlap by 0.61 of the small radius, more than the admission's default 0.5
text = text.replace("\ngrains:\n", "\ngrains:\n  max_overlap: 0.7\n", 1)
open(sys.argv[2], "w").write("# scene.yaml with every radius x 1.15: the grains press on the cavity.\n" + text)
PY
for case in placed confined; do
  src=$here/scene.yaml; [ $case = confined ] && src=$runs/confined.yaml
  for lin in umfpack cholmod; do
    sed "s/linear: umfpack /linear: $lin /" "$src" > "$runs/$case-$lin.yaml"
    sed -i "s|\.\./\.\./meshes/|$root/meshes/|" "$runs/$case-$lin.yaml"
    "$gembem" run "$runs/$case-$lin.yaml" -o "$runs/$case-$lin" --overwrite --quiet
  done
done
for case in placed confined; do
  /usr/bin/python3 "$here/figures.py" "$runs/$case-umfpack" "$here/$case" "Cavity packing, $case (UMFPACK)"
done
/usr/bin/python3 - "$runs" <<'PY'
import csv, math, sys
runs = sys.argv[1]
print("| case | solver | iterations | seconds | largest fixing force [kgf] | largest overlap [cm] | contacts with the cavity | ||K-K^t||/||K|| |")
print("|---|---|---|---|---|---|---|---|")
pos = {}
for case in ("placed", "confined"):
    for lin in ("umfpack", "cholmod"):
        d = f"{runs}/{case}-{lin}"
        s = list(csv.DictReader(open(f"{d}/steps.csv")))[-1]
        cs = list(csv.DictReader(open(f"{d}/state_contacts.csv")))
        ov = max([float(c["overlap"]) for c in cs] + [0.0])
        nb = sum(1 for c in cs if c["j"].startswith("p"))
        asym = [l.split(":")[1].split("#")[0].strip() for l in open(f"{d}/host_info.yaml") if l.startswith("asymmetry")][0]
        pos[case, lin] = [(float(g["x"]), float(g["y"])) for g in csv.DictReader(open(f"{d}/state_grains.csv"))]
        print(f"| {case} | {lin.upper()} | {s['iterations']} | {float(s['seconds']):.3f} | {float(s['max_fixing_force']):.2e} | {ov:.2e} | {nb} | {float(asym):.2e} |")
for case in ("placed", "confined"):
    d = max(math.hypot(a[0] - b[0], a[1] - b[1]) for a, b in zip(pos[case, "umfpack"], pos[case, "cholmod"]))
    print(f"\n{case}: final grain positions of UMFPACK and CHOLMOD differ by {d:.2e} cm at most.")
PY
