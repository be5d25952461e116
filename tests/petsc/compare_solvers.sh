#!/usr/bin/env bash
# solver.linear: petsc under `mpirun -np 2` (MUMPS's Cholesky; CG preconditioned by GAMG on the
# hybrid scene) against CHOLMOD in one process, on the same scene (compare_runs.py):
#   jammed: a jammed packing of 10 000 discs (tools/jammed_packing.sh) compressed in two steps of
#     isotropic stress control to 6e5 dyn/cm (accuracy a = 100 dyn);
#   hybrid: tests/hybrid/load_grains.yaml, 27 grains in the cavity of an elastic host.
# The first linear solves agree to 1e-10 relative (the same matrix and right-hand side: only
# rounding differs). The runs then agree to their accuracy: jammed, stresses within 2 a / L (each
# axis's wall force is within a of its target, L = 76.7 cm the box's side: 2.6 dyn/cm), strains within
# 1e-5 (the accuracy's a on a disc of 0.9 cm is ~1e2 dyn/cm, ~1e-6 of strain at the packing's
# modulus ~1e8 dyn/cm (4e4 dyn/cm for 4e-4 of strain in the first step): ten times that, and 1/40
# of a step's strain); hybrid, the host's displacements and reactions within 1e-6 of their largest
# value (a = 1e-9 kgf on forces of ~1e2 kgf). Then the scene reader's checks of solver.petsc.
#   compare_solvers.sh MPIEXEC GEMBEM BUILD_DIR WORK_DIR jammed|hybrid
set -euo pipefail
mpiexec=$1 gembem=$2 build=$3 work=$4 case=$5
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
source "$root/tests/scene.sh"
rm -rf "$work"
mkdir -p "$work"
# One BLAS thread per rank (2 ranks on 2 cores); Open MPI as root in containers and CI.
export OPENBLAS_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
launch=("$mpiexec" -np 2)
"$mpiexec" --version 2>&1 | grep -q "Open MPI" && launch+=(--oversubscribe)
if [ "$case" = jammed ]; then
  "$root/tools/jammed_packing.sh" "$build" "$work/pack" 10000 1 10 > /dev/null
  scene() { # OUT LINEAR [PETSC]: the packing's scene with the global solver and a linear solver
    scene_edit "$work/pack/scene.yaml" -o "$work/pack/$1.yaml" \
      --set "solver={method: global, linear: $2, accuracy: 100, max_iterations: 2000000}" ${3:+--add "solver.petsc=$3"} \
      --set 'loading.0.isotropic={stress: 6.0e5, steps: 2}'   # of 1.5e5 in 1 step
  }
  dir=$work/pack tols=(2.6 1e-5)
  # CG + GAMG took 348 s on this packing (a poor case for algebraic multigrid, docs/scaling.md):
  # it is compared on the hybrid scene only
  solvers=mumps
else
  scene() { # OUT LINEAR [PETSC]
    scene_edit "$root/tests/hybrid/load_grains.yaml" -o "$work/$1.yaml" --set solver.linear="$2" \
      ${3:+--add "solver.petsc=$3"}
  }
  dir=$work tols=(1 1 1e-6) solvers="mumps gamg"
fi
scene cholmod cholmod
scene mumps petsc
[ "$case" = hybrid ] && scene gamg petsc "{ksp: cg, pc: gamg}"
GB_DUMP_FIRST_SOLVE=$work/x_cholmod "$gembem" run "$dir/cholmod.yaml" -o "$work/cholmod" --quiet
fail=0
for s in $solvers; do
  GB_DUMP_FIRST_SOLVE=$work/x_$s "${launch[@]}" "$gembem" run "$dir/$s.yaml" -o "$work/$s" --quiet
  grep -q "ranks: 2 " "$work/$s/run_info.yaml" || { echo "FAIL $s: run_info.yaml does not say 2 ranks"; fail=1; }
  echo "-- $s, 2 ranks, against CHOLMOD"
  /usr/bin/python3 "$here/compare_runs.py" "$work/x_cholmod" "$work/x_$s" "$work/cholmod" "$work/$s" 1e-10 \
    "${tols[@]}" || fail=1
done
# The scene reader: a misspelt KSP, and a petsc section for another linear solver (exit 2).
expect_refusal() { # LINEAR PETSC MESSAGE
  scene bad "$1" "$2"
  if "$gembem" run "$dir/bad.yaml" -o "$work/bad" > "$work/bad.log" 2>&1; then rc=0; else rc=$?; fi
  if [ "$rc" -eq 2 ] && grep -q "$3" "$work/bad.log"; then echo "ok   refused: $(head -1 "$work/bad.log")"
  else echo "FAIL expected exit 2 and '$3', got $rc: $(cat "$work/bad.log")"; fail=1; fi
}
expect_refusal petsc "{ksp: cgg}" "solver.petsc.ksp: expected one of"
expect_refusal cholmod "{pc: gamg}" "solver.petsc: applies to linear: petsc only"
exit $fail
