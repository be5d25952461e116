#!/usr/bin/env bash
# A hybrid run gives the same bytes with OPENBLAS_NUM_THREADS=1 and 2 (same CPU, same OpenBLAS
# kernel): the BEM's LU and the host's K u run on one BLAS thread (src/core/blas.h). The scene is
# load_grains.yaml with a host of 390 elements (780 DOFs, enough for OpenBLAS to thread dgetrf and
# the cavity's 300 x 300 dgemv, which it splits by columns) and one step per host stage. Every
# file of the two run directories is compared byte for byte but run_info.yaml (timings, the
# thread count), .lock (the writer's pid and start), steps.csv's clock and the checkpoint (which
# holds it).
#   run_blas_threads.sh GEMBEM
set -u
gembem=$1; dir=$(cd "$(dirname "$0")" && pwd); out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
sed "s/elements: {bottom: 5, right: 5, top: 5, left: 5, cavity: 24}/elements: {bottom: 60, right: 60, top: 60, left: 60, cavity: 150}/; s|\.\./\.\./meshes/|$dir/../../meshes/|; s/steps: 2,/steps: 1,/" \
  "$dir/load_grains.yaml" > "$out/scene.yaml"
# each run in the same directory name (state.yaml's comment names it), the first moved aside
for t in 1 2; do
  OPENBLAS_NUM_THREADS=$t "$gembem" run "$out/scene.yaml" -o "$out/run" --quiet 2>/dev/null ||
    { echo "FAIL: the run with OPENBLAS_NUM_THREADS=$t failed"; exit 1; }
  # steps.csv's seconds (column 12) are a clock, and checkpoint.txt holds steps.csv's last bytes
  cut -d, -f12 --complement "$out/run/steps.csv" > "$out/run/steps_no_clock.csv"
  rm -f "$out/run/steps.csv" "$out/run/checkpoint.txt"
  mv "$out/run" "$out/t$t"
done
[ "$(head -1 "$out/t1/steps_no_clock.csv" | cut -d, -f11-12)" = "max_fixing_force,contacts" ] ||
  { echo "FAIL: steps.csv's columns moved: update the clock's column here"; exit 1; }
differ=$(diff -rq -x run_info.yaml -x .lock "$out/t1" "$out/t2")
[ -z "$differ" ] || { echo "FAIL: OPENBLAS_NUM_THREADS=1 and 2 give other bytes:"; echo "$differ"; exit 1; }
echo "ok: $(find "$out/t1" -type f | wc -l) files of the run directory, the same bytes with 1 and 2 BLAS threads"
