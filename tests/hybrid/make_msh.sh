#!/usr/bin/env bash
# Writes the .msh files that gmsh makes of .geo files, as its users do: MSH 2.2 and 4.1,
# ASCII and binary, into OUT_DIR as NAME_msh22.msh, NAME_msh22_bin.msh, NAME_msh41.msh and
# NAME_msh41_bin.msh for each NAME.geo.   make_msh.sh GMSH OUT_DIR GEO...
set -euo pipefail
gmsh=$1; out=$2; shift 2
mkdir -p "$out"
for geo in "$@"; do
  name=$(basename "$geo" .geo)
  for format in msh22 msh41; do
    "$gmsh" -1 "$geo" -format $format -o "$out/${name}_$format.msh" > "$out/${name}_$format.log"
    "$gmsh" -1 "$geo" -format $format -bin -o "$out/${name}_${format}_bin.msh" > "$out/${name}_${format}_bin.log"
  done
done
