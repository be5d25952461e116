#!/usr/bin/env bash
# Benchmark of the granular solvers (not a test) on jammed random packings of the paper's three
# sizes (Table 3: diameters 0.6, 0.9, 1.2 cm, equal area per size, kn, kt = 1e8, 7e7 dyn/cm,
# phi = 25 deg, a = 100 dyn). A packing: gb_packgen's densest deposition, overfilled to porosity
# 0.17 by tools/overfill.py (centres shrunk: overlaps of a few per cent), relaxed with the walls
# fixed by the global solver (the preparation); then STEPS load steps of isotropic stress control,
# each adding 5 % of the stress the preparation left, with each solver (build/bench_jammed).
#   [SOLVERS="reference cholmod umfpack"] [STEPS=4] [PREP_CAP=30000] tools/bench_gem.sh [BUILD_DIR] [N ...]
#   (default: build, 1000 10000 100000)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/${1:-build}; shift || true
sizes=${*:-1000 10000 100000}
steps=${STEPS:-4}
out=$root/runs/bench_gem
mkdir -p "$out"
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); $(date -u +%Y-%m-%d)"
echo "threads: OPENBLAS_NUM_THREADS=${OPENBLAS_NUM_THREADS:-default}, OMP_NUM_THREADS=${OMP_NUM_THREADS:-default}"
printf "| solver | N | contacts | preparation iterations (s) | stress left s_r [dyn/cm] | iterations per load step | s per iteration | ns per contact-iteration | load steps s |\n"
printf "|---|---|---|---|---|---|---|---|---|\n"
for n in $sizes; do
  d=$out/n$n; mkdir -p "$d"
  "$build/gb_packgen" --n "$n" --diameters 0.6,0.9,1.2 --seed 1 --out "$d/grains.csv" >/dev/null
  box=$(/usr/bin/python3 "$root/tools/overfill.py" "$d/grains.csv" "$d/grains.box.yaml" 0.17 "$d/jammed.csv")
  cat > "$d/scene_jammed.yaml" <<YAML
gembem: 1
units: {length: cm, force: dyn}
materials:
  grain_grain: {kn: 1.0e8, kt: 7.0e7, friction_deg: 25}
  grain_wall:  {kn: 1.0e8, kt: 7.0e7, friction_deg: 0}
grains: {file: jammed.csv}
$box
solver: {accuracy: 100, max_iterations: 400000}
loading:  # not used by bench_jammed, which drives the walls itself
  - isotropic: {stress: 1.5e5, steps: 1}
YAML
  for s in ${SOLVERS:-reference cholmod umfpack}; do
    "$build/bench_jammed" "$d/scene_jammed.yaml" "$steps" "$s" "${PREP_CAP:-30000}"
  done
done
