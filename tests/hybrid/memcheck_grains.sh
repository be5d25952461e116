#!/usr/bin/env bash
# The 27-grain hybrid loading (tests/hybrid/load_grains.yaml) with CHOLMOD under valgrind's
# memcheck: no read of uninitialised memory. AddressSanitizer does not see such reads; one (the
# first conjugate-gradient direction computed as z + 0 x garbage, NaN when the garbage was) made
# runs of the same scene depend on the heap's history, e.g. on the length of the working
# directory's path (validation/localisation/README.md).
#   memcheck_grains.sh VALGRIND GEMBEM
set -u
valgrind=$1 gembem=$2
root=$(cd "$(dirname "$0")/../.." && pwd)
source "$root/tests/scene.sh"
work=$(mktemp -d)
scene_edit "$root/tests/hybrid/load_grains.yaml" -o "$work/scene.yaml" --set solver.linear=cholmod
grep -q 'linear: cholmod' "$work/scene.yaml" || { echo "FAIL the scene does not use CHOLMOD"; exit 1; }
# valgrind does not run AVX-512: a forced OpenBLAS kernel (OPENBLAS_CORETYPE=SkylakeX) would stop
# at an illegal instruction, so OpenBLAS picks its kernel from the CPU valgrind emulates.
env -u OPENBLAS_CORETYPE OPENBLAS_NUM_THREADS=1 "$valgrind" -q --error-exitcode=9 "$gembem" run "$work/scene.yaml" -o "$work/run" --quiet \
  > "$work/log" 2>&1
rc=$?
if [ $rc -eq 0 ]; then echo "ok   memcheck: no error"; rm -rf "$work"; exit 0; fi
grep -m 20 -A 6 'uninitialised\|Invalid' "$work/log"
echo "FAIL memcheck: exit $rc (log in $work/log)"
exit 1
