#!/usr/bin/env bash
# Benchmark of the granular solvers (not a test) on jammed random packings of the paper's three
# sizes (Table 3: diameters 0.6, 0.9, 1.2 cm, equal area per size, kn, kt = 1e8, 7e7 dyn/cm,
# phi = 25 deg, a = 100 dyn). A packing: gb_packgen's densest deposition, shrunk to porosity 0.15
# and relaxed frictionless with the walls fixed by gb_jam (FIRE) to |F| <= 10 dyn per disc, an
# equilibrium that friction keeps; it is cached in runs/bench_gem/nN/ (1e5 discs take 20-50
# minutes). Then STEPS load steps of isotropic stress control, each adding 5 % of the stress the
# packing starts with, with each solver (build/bench_jammed). Single-threaded BLAS unless the
# caller sets OPENBLAS_NUM_THREADS / OMP_NUM_THREADS.
#   [SOLVERS="reference cholmod umfpack"] [STEPS=4] tools/bench_gem.sh [BUILD_DIR] [N ...]
#   (default: build, 1000 10000 100000)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/${1:-build}; shift || true
sizes=${*:-1000 10000 100000}
steps=${STEPS:-4}
out=$root/runs/bench_gem
export OPENBLAS_NUM_THREADS=${OPENBLAS_NUM_THREADS:-1} OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}
mkdir -p "$out"
echo "machine: $(nproc --all) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); $(date -u +%Y-%m-%d)"
echo "threads: OPENBLAS_NUM_THREADS=$OPENBLAS_NUM_THREADS, OMP_NUM_THREADS=$OMP_NUM_THREADS; load average $(cut -d' ' -f1-3 /proc/loadavg)"
printf "| solver | N | contacts | preparation iterations (s) | stress s_r [dyn/cm] | iterations per load step | s per iteration | ns per contact-iteration | load steps s |\n"
printf "|---|---|---|---|---|---|---|---|---|\n"
for n in $sizes; do
  d=$out/n$n; mkdir -p "$d"
  if [ ! -s "$d/fire.csv" ] || [ ! -s "$d/fire.box" ]; then
    "$build/gb_packgen" --n "$n" --diameters 0.6,0.9,1.2 --seed 1 --out "$d/grains.csv" >/dev/null
    box=$(sed -n 's/^box: {left: \([^,]*\), right: \([^,]*\), bottom: \([^,]*\), top: \([^}]*\)}$/\1,\2,\3,\4/p' "$d/grains.box.yaml")
    "$build/gb_jam" "$d/grains.csv" --box "$box" --porosity 0.15 --kn 1e8 --tol 10 --out "$d/fire.csv" \
      > "$d/fire.box" 2> "$d/fire.log"
  fi
  echo "n = $n: $(cat "$d/fire.log" 2>/dev/null || echo 'packing from an earlier run')" >&2
  cat > "$d/scene_fire.yaml" <<YAML
gembem: 1
units: {length: cm, force: dyn}
materials:
  grain_grain: {kn: 1.0e8, kt: 7.0e7, friction_deg: 25}
  grain_wall:  {kn: 1.0e8, kt: 7.0e7, friction_deg: 0}
grains: {file: fire.csv}
$(cat "$d/fire.box")
solver: {accuracy: 100, max_iterations: 2000000}
loading:  # not used by bench_jammed, which drives the walls itself
  - isotropic: {stress: 1.5e5, steps: 1}
YAML
  for s in ${SOLVERS:-reference cholmod umfpack}; do
    "$build/bench_jammed" "$d/scene_fire.yaml" "$steps" "$s" 100
  done
done
