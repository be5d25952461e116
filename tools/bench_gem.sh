#!/usr/bin/env bash
# Benchmark of the granular solvers (not a test) on jammed random packings of the paper's three
# sizes (tools/jammed_packing.sh: gembem pack grows them to porosity 0.15, frictionless by FIRE
# to |F| <= 10 dyn per disc, seed 1; cached in runs/bench_gem/nN/). Then
# STEPS load steps of isotropic stress control, each adding 5 % of the stress the packing starts
# with, with each solver (build/bench_jammed). Single-threaded BLAS unless the
# caller sets OPENBLAS_NUM_THREADS / OMP_NUM_THREADS.
#   [SOLVERS="reference cholmod umfpack"] [STEPS=4] tools/bench_gem.sh [BUILD_DIR] [N ...]
#   (default: build, 1000 10000 100000)
set -euo pipefail
source "$(dirname "$0")/lib.sh"
bench_args "$@"
export OPENBLAS_NUM_THREADS=${OPENBLAS_NUM_THREADS:-1} OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}
mkdir -p "$out"
echo "machine: $(nproc --all) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); $(date -u +%Y-%m-%d)"
echo "threads: OPENBLAS_NUM_THREADS=$OPENBLAS_NUM_THREADS, OMP_NUM_THREADS=$OMP_NUM_THREADS; load average $(cut -d' ' -f1-3 /proc/loadavg)"
printf "| solver | N | contacts | preparation iterations (s) | stress s_r [dyn/cm] | accuracy a [dyn] | iterations per load step | s per iteration | ns per contact-iteration | load steps s | peak memory [MB] |\n"
printf "|---|---|---|---|---|---|---|---|---|---|---|\n"
for n in $sizes; do
  d=$out/n$n
  KEEP=1 "$root/tools/jammed_packing.sh" "$build" "$d" "$n" 1 10
  echo "n = $n: $(cat "$d/jammed.log")" >&2
  for s in ${SOLVERS:-reference cholmod umfpack}; do
    "$build/bench_jammed" "$d/scene.yaml" "$steps" "$s" 100 "${ACCURACY:-target}"
  done
done
