#!/usr/bin/env bash
# The flagship demo: installs the dependencies, builds gembem, and runs
#  1. the 27-grain cavity packing of the hybrid paper (grains in the cavity of an elastic body,
#     solved with the host as one sparse system), leaving its figures in runs/demo-cavity;
#  2. the three-disc shear test of Kishino (1989), case 1, printing its stress ratios next to the
#     paper's Table 2.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)" >/dev/null

build/gembem run validation/cavity_packing/scene.yaml -o runs/demo-cavity --overwrite
/usr/bin/python3 validation/cavity_packing/figures.py runs/demo-cavity runs/demo-cavity/packing "Cavity packing (UMFPACK)"
echo "Cavity packing: runs/demo-cavity (packing_grains.png, packing_cavity.png, host_field.vtu for ParaView,"
echo "host_particles.csv, steps.csv, snapshots/*.vtp)"
echo

build/gembem run validation/three_discs/case1.yaml -o runs/demo --overwrite
echo
echo "Three discs, Table 1 case 1 (kn = 1e8 dyn/cm, a = 100 dyn): stress ratio (s1 - s2)/(s1 + s2)"
(cd validation/three_discs && /usr/bin/python3 table2.py ../../runs/demo)
echo
echo "Run directory: runs/demo (steps.csv, state.yaml, snapshots/*.vtp for ParaView, scene.yaml, run_info.yaml)"
