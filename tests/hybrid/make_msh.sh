#!/usr/bin/env bash
# Writes the .msh files that gmsh makes of a .geo, as its users do (issue 23): MSH 2.2 and 4.1,
# ASCII and binary, into OUT_DIR as NAME_msh22.msh, NAME_msh22_bin.msh, NAME_msh41.msh and
# NAME_msh41_bin.msh.   make_msh.sh GMSH GEO OUT_DIR
set -euo pipefail
gmsh=$1; geo=$2; out=$3; name=$(basename "$geo" .geo)
mkdir -p "$out"
for format in msh22 msh41; do
  "$gmsh" -1 "$geo" -format $format -o "$out/${name}_$format.msh" > "$out/${name}_$format.log"
  "$gmsh" -1 "$geo" -format $format -bin -o "$out/${name}_${format}_bin.msh" > "$out/${name}_${format}_bin.log"
done
