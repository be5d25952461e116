#!/usr/bin/env bash
# A run gives the same bytes with OPENBLAS_NUM_THREADS=1 and 2 (same CPU, same OpenBLAS kernel):
# the BEM's LU, the host's K u and the global solver's sparse factorisations and solves run on one
# BLAS thread (src/core/blas.h). Every file of the two run directories is compared byte for byte
# but run_info.yaml (timings, the thread count), .lock (the writer's pid and start), steps.csv's
# clock and the checkpoint (which holds it).
#   run_blas_threads.sh GEMBEM
#     load_grains.yaml with a host of 390 elements (780 DOFs, enough for OpenBLAS to thread dgetrf
#     and the cavity's 300 x 300 dgemv, which it splits by columns) and one step per host stage.
#   run_blas_threads.sh GEMBEM GB_PACKGEN cholmod|umfpack
#     a friction relaxation of 1000 discs (gb_packgen's push packing of the solver benchmark,
#     tools/solver_packing.sh) by the global solver: 3003 unknowns, where CHOLMOD's analysis
#     chooses its supernodal factorisation (flops / nonzeros of the factor about 43, its switch 40)
#     and UMFPACK's fronts are dense enough for OpenBLAS to thread. Without the single BLAS
#     thread both gave other bytes at 2 threads (CHOLMOD: 212 iterations with 1, 189 with 2).
set -u
gembem=$1; dir=$(cd "$(dirname "$0")" && pwd); out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
if [ $# -eq 1 ]; then
  sed "s/elements: {bottom: 5, right: 5, top: 5, left: 5, cavity: 24}/elements: {bottom: 60, right: 60, top: 60, left: 60, cavity: 150}/; s|\.\./\.\./meshes/|$dir/../../meshes/|; s/steps: 2,/steps: 1,/" \
    "$dir/load_grains.yaml" > "$out/scene.yaml"
else
  packgen=$2 linear=$3
  "$packgen" --method push --n 1000 --diameters 0.6,0.9,1.2 --porosity 0.18 --max-overlap 0.015 --seed 1 \
    --out "$out/packing.csv" > /dev/null 2>&1 || { echo "FAIL: gb_packgen failed"; exit 1; }
  cat > "$out/scene.yaml" <<YAML
gembem: 1
units: {length: cm, force: dyn}
materials:
  grain_grain: {kn: 1e8, kt: 7e7, friction_deg: 25}
  grain_wall: {kn: 1e8, kt: 7e7, friction_deg: 0}
grains: {file: packing.csv}
$(grep '^box:' "$out/packing.box.yaml")
solver: {method: global, linear: $linear, accuracy: 1000, max_iterations: 1000}
loading:
  - relax: {steps: 1}
output: {measures_every: 0, localisation: false}
YAML
fi
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
