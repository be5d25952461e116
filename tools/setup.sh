#!/usr/bin/env bash
# Installs gembem's build and run dependencies, all Debian 12 packages, by name.
#   tools/setup.sh                   what building, testing and the demo need
#   tools/setup.sh --with-paraview   also ParaView and Xvfb, the optional extra that draws a run's VTK
#                                    files off-screen (tools/paraview_render.py, ctest paraview_render)
set -euo pipefail
packages=(build-essential cmake pkg-config libsuitesparse-dev libopenblas-dev liblapacke-dev
          gmsh libgmsh-dev libfyaml-dev libqhull-dev python3-matplotlib python3-numpy python3-scipy python3-yaml snakemake valgrind)
case "${1:-}" in
  "") ;;
  --with-paraview) packages+=(paraview xvfb xauth) ;;   # Debian's pvpython renders through X: Xvfb
  *) echo "usage: tools/setup.sh [--with-paraview]" >&2; exit 2 ;;
esac
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}"
fi
