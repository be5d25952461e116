#!/usr/bin/env bash
# Installs the dependencies, builds gembem and runs the whole test suite.
#   tools/test.sh                  Release build in build/, ctest (PETSc's solver if installed: AUTO)
#   tools/test.sh --sanitize       the same with AddressSanitizer + UBSan, in build-asan/
#   tools/test.sh --with-petsc     also installs PETSc and Open MPI (tools/setup.sh --with-petsc) and
#                                  requires the PETSc solver (GB_WITH_PETSC=ON): its ctests run
#   tools/test.sh --without-petsc  builds without it (GB_WITH_PETSC=OFF), in build-nopetsc/
#   (--sanitize combines with either; arguments after -- go to ctest, e.g. -- -L petsc)
set -euo pipefail
cd "$(dirname "$0")/.."
dir=build; flags=(-DCMAKE_BUILD_TYPE=Release); setup=(); ctest_args=()
while [ $# -gt 0 ]; do
  arg=$1; shift
  case "$arg" in
    --) ctest_args=("$@"); break ;;
    --sanitize)
      dir=build-asan; flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DGB_SANITIZE=ON)
      export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
      export LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp ;;   # leaks inside gmsh, not ours
    --with-petsc) setup=(--with-petsc); petsc=ON ;;
    --without-petsc) petsc=OFF ;;
    *) echo "usage: tools/test.sh [--sanitize] [--with-petsc | --without-petsc] [-- CTEST_ARGS]" >&2; exit 2 ;;
  esac
done
[ "${petsc:-}" = OFF ] && dir=$dir-nopetsc
tools/setup.sh "${setup[@]}"
flags+=(-DGB_WITH_PETSC="${petsc:-AUTO}")
cmake -S . -B "$dir" "${flags[@]}" >/dev/null
cmake --build "$dir" -j "$(nproc)"
ctest --test-dir "$dir" --output-on-failure -j "$(nproc)" "${ctest_args[@]}"
