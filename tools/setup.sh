#!/usr/bin/env bash
# Installs gembem's build and run dependencies, all Debian 12 packages, by name.
#   tools/setup.sh                   what building, testing and the demo need
#   tools/setup.sh --with-paraview   also ParaView and Xvfb, the optional extra that draws a run's VTK
#                                    files off-screen (tools/paraview_render.py, ctest demo_paraview_render)
#   tools/setup.sh --with-petsc      also PETSc with Open MPI, for solver.linear: petsc (optional,
#                                    docs/scaling.md; CMake builds it when found, GB_WITH_PETSC)
#   (both extras may be given)
set -euo pipefail
packages=(build-essential cmake pkg-config libsuitesparse-dev libopenblas-dev liblapacke-dev
          gmsh libgmsh-dev libfyaml-dev libqhull-dev python3-matplotlib python3-numpy python3-scipy python3-yaml snakemake valgrind)
for extra in "$@"; do
  case "$extra" in
    --with-paraview) packages+=(paraview xvfb xauth) ;;   # Debian's pvpython renders through X: Xvfb
    --with-petsc) packages+=(libpetsc-real-dev openmpi-bin) ;;
    *) echo "usage: tools/setup.sh [--with-paraview] [--with-petsc]" >&2; exit 2 ;;
  esac
done
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}"
fi
