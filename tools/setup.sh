#!/usr/bin/env bash
# Installs gembem's build and run dependencies, all Debian 12 packages, by name.
#   tools/setup.sh               what the build, the tests and the demo need
#   tools/setup.sh --with-petsc  and PETSc with Open MPI, for solver.linear: petsc (optional,
#                                docs/scaling.md; CMake builds it when found, GB_WITH_PETSC)
set -euo pipefail
packages=(build-essential cmake pkg-config libsuitesparse-dev libopenblas-dev liblapacke-dev
          gmsh libgmsh-dev libfyaml-dev libqhull-dev python3-matplotlib python3-numpy python3-scipy python3-yaml snakemake valgrind)
[ "${1:-}" = "--with-petsc" ] && packages+=(libpetsc-real-dev openmpi-bin)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}"
fi
