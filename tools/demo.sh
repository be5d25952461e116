#!/usr/bin/env bash
# The demo: installs the dependencies, builds gembem, then
#  1. packs 300 grains into the circular cavity of an elastic 10 x 10 cm body (gembem pack), lets
#     grains and body settle together, compresses the body biaxially by 3 % in 30 steps, and draws
#     the figures a researcher looks at first into runs/demo/figures, printing each with a line on
#     what it shows (examples/demo/: the three scenes and demo.py);
#  2. runs the three-disc shear test of Kishino (1989), case 1, and prints its stress ratios next
#     to the paper's Table 2.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)" >/dev/null

echo "== Grains in the cavity of an elastic body, compressed (examples/demo: pack.yaml, settle.yaml, compress.yaml)"
PYTHONPATH=python /usr/bin/python3 examples/demo/demo.py runs/demo
echo "Runs: runs/demo/packed (pack_info.yaml), runs/demo/settled, runs/demo/compressed (steps.csv, host_steps.csv,"
echo "localisation.csv, fields/, host_field.vtu, grains.pvd and contacts.pvd for ParaView)"
echo

echo "== Three discs, Kishino (1989) Table 1 case 1 (kn = 1e8 dyn/cm, a = 100 dyn): stress ratio (s1 - s2)/(s1 + s2)"
build/gembem run validation/three_discs/case1.yaml -o runs/demo-three-discs --overwrite --quiet
(cd validation/three_discs && /usr/bin/python3 table2.py ../../runs/demo-three-discs)
