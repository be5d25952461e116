#!/usr/bin/env bash
# The solver benchmark's packing and scenes (tools/bench_solver.sh): a packing that gembem did not
# make, so that no solver starts from a state one of them prepared. gb_packgen --method push: N
# discs of diameters 0.6, 0.9, 1.2 cm (equal area per size) placed at random in a square box of
# porosity 0.18, pushed apart until every overlap is at most 0.015 of the smaller radius (the
# discs then press on each other and on the walls: the relaxations have work to do). Scenes, with
# the constants of Kishino's Table 3 (kn, kt = 1e8, 7e7 dyn/cm, a = 100 dyn), walls fixed:
#   relax_frictionless.yaml, relax_friction.yaml: one relax step from the packing, grain-grain
#     friction 0 and 25 deg (walls frictionless in both);
#   relax_friction_reference.yaml: the same with friction by the reference iteration (the
#     fallback state for the path when the global solver's relaxation fails);
#   path.yaml: from the final state of a friction relaxation, 20 steps of de1 = 0.0005 (1 %
#     vertical compression; compression positive) with the side walls fixed: oedometric.
#
#   [KEEP=1] [PACKING=FILE.csv] [PERTURB=f] [SOLVER=global|reference] [LINEAR=cholmod|umfpack]
#   [NEWTON=damped|line_search] [THREADS=1] (solver.threads: the contacts' updates on THREADS cores)
#   [KN_SCALE=1] (kn, kt and the accuracy a times KN_SCALE: the same packing, stiffer springs)
#   [MAX_ITERATIONS=1000] [PATH_MAX_ITERATIONS=500] [REF_MAX_ITERATIONS=1000000]
#   tools/solver_packing.sh BUILD_DIR OUT_DIR N SEED [STATE_RUN_DIR]
#
# OUT_DIR/packing.csv (+ packing.box.yaml): made by gb_packgen (seed SEED), kept if KEEP=1 and
# present, or copied from PACKING (its .box.yaml beside it) so that variants share one packing.
# PERTURB=f: the scenes use packing_perturbed.csv, every centre moved by f r times a uniform
# random number in [-1, 1] per coordinate (Python's Mersenne twister seeded by SEED: the same
# file on every machine), to see whether a solver's result hangs on the last bits of the input.
# STATE_RUN_DIR (or STATE=): the run whose state.yaml path.yaml starts from (default
# OUT_DIR/relax_friction). MAX_ITERATIONS caps each relaxation, PATH_MAX_ITERATIONS each load
# step of the path (before its cut-backs), REF_MAX_ITERATIONS the reference relaxation (it
# needs thousands of iterations where the global solver needs tens).
set -euo pipefail
source "$(dirname "$0")/lib.sh"
[ $# -ge 4 ] && [ $# -le 5 ] || {
  echo "usage: tools/solver_packing.sh BUILD_DIR OUT_DIR N SEED [STATE_RUN_DIR]" >&2; exit 2; }
build=$1 out=$2 n=$3 seed=$4 state=${5:-${STATE:-}}
solver=${SOLVER:-global} linear=${LINEAR:-cholmod} newton=${NEWTON:-damped} threads=${THREADS:-1}
s=${KN_SCALE:-1}
read -r kn kt acc < <(awk -v s="$s" 'BEGIN { printf "%.17g %.17g %.17g\n", 1.0e8 * s, 7.0e7 * s, 100 * s }')
case $newton in damped|line_search) ;; *) echo "solver_packing.sh: NEWTON must be damped or line_search" >&2; exit 2;; esac
[ "$newton" = damped ] || [ "$linear" = umfpack ] || { echo "solver_packing.sh: NEWTON=line_search needs LINEAR=umfpack" >&2; exit 2; }
case $solver in global|reference) ;; *) echo "solver_packing.sh: SOLVER must be global or reference" >&2; exit 2;; esac
case $linear in cholmod|umfpack) ;; *) echo "solver_packing.sh: LINEAR must be cholmod or umfpack" >&2; exit 2;; esac
mkdir -p "$out"
out=$(cd "$out" && pwd)
state=${state:-$out/relax_friction}

# The packing: copied, kept or made.
if [ -n "${PACKING:-}" ]; then
  src_box=${PACKING%.csv}.box.yaml
  [ "$PACKING" -ef "$out/packing.csv" ] || cp "$PACKING" "$out/packing.csv"
  [ "$src_box" -ef "$out/packing.box.yaml" ] || cp "$src_box" "$out/packing.box.yaml"
elif [ "${KEEP:-0}" != 1 ] || [ ! -s "$out/packing.csv" ] || [ ! -s "$out/packing.box.yaml" ]; then
  "$build/gb_packgen" --method push --n "$n" --diameters 0.6,0.9,1.2 --porosity 0.18 \
    --max-overlap 0.015 --seed "$seed" --out "$out/packing.csv" >&2
fi
grains=packing.csv
if [ -n "${PERTURB:-}" ]; then
  /usr/bin/python3 - "$out/packing.csv" "$out/packing_perturbed.csv" "$PERTURB" "$seed" <<'PY'
import random, sys
src, dst, f, seed = sys.argv[1], sys.argv[2], float(sys.argv[3]), int(sys.argv[4])
rng = random.Random(seed)
with open(src) as a, open(dst + ".part", "w") as b:
    b.write(a.readline())
    for line in a:
        x, y, r = map(float, line.split(","))
        x += f * r * rng.uniform(-1.0, 1.0)
        y += f * r * rng.uniform(-1.0, 1.0)
        b.write("%.17g,%.17g,%.17g\n" % (x, y, r))
import os
os.replace(dst + ".part", dst)
PY
  grains=packing_perturbed.csv
fi
box=$(grep '^box:' "$out/packing.box.yaml")

# solver: line for a method and an iteration cap (linear only for the global solver)
solver_line() {
  if [ "$1" = global ]; then
    echo "solver: {method: global, linear: $linear, newton: $newton, threads: $threads, accuracy: $acc, max_iterations: $2}"
  else
    echo "solver: {method: reference, threads: $threads, accuracy: $acc, max_iterations: $2}"
  fi
}
# A relaxation scene: friction, method, cap, file
relax_scene() {
  cat > "$4" <<YAML
# Written by tools/solver_packing.sh: one relax step (nothing imposed, walls fixed) from the
# packing of $n discs, seed $seed${PERTURB:+, centres perturbed by $PERTURB r}.
gembem: 1
units: {length: cm, force: dyn}
$(table3_materials "$1" "$kn" "$kt")
grains: {file: $grains}
$box
$(solver_line "$2" "$3")
loading:
  - relax: {steps: 1}
output: {measures_every: 0, localisation: false}   # the benchmark times the solver, not the per-step measures
YAML
}
max_it=${MAX_ITERATIONS:-1000}
relax_scene 0 "$solver" "$max_it" "$out/relax_frictionless.yaml"
relax_scene 25 "$solver" "$max_it" "$out/relax_friction.yaml"
relax_scene 25 reference "${REF_MAX_ITERATIONS:-1000000}" "$out/relax_friction_reference.yaml"
cat > "$out/path.yaml" <<YAML
# Written by tools/solver_packing.sh: oedometric compression (de1 > 0 compresses, the side walls
# fixed) of 1 % in 20 steps from the final state of a friction relaxation.
gembem: 1
units: {length: cm, force: dyn}
$(table3_materials 25 "$kn" "$kt")
initial_state: $state/state.yaml
$(solver_line "$solver" "${PATH_MAX_ITERATIONS:-500}")
loading:
  - strain: {de1: 0.0005, de2: 0, steps: 20}
output: {measures_every: 0, localisation: false}   # as the relaxations: the solver, not the measures
YAML
