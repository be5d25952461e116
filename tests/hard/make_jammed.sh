#!/usr/bin/env bash
# Test fixture: a jammed packing of 300 discs (gb_packgen's deposit, shrunk to porosity 0.15 and
# relaxed frictionless by gb_jam), and a scene that starts from it.
#   make_jammed.sh BUILD_DIR OUT_DIR
set -euo pipefail
build=$1 out=$2
mkdir -p "$out"
"$build/gb_packgen" --n 300 --diameters 0.6,0.9,1.2 --seed 3 --out "$out/deposit.csv" >/dev/null
box=$(sed -n 's/^box: {left: \([^,]*\), right: \([^,]*\), bottom: \([^,]*\), top: \([^}]*\)}$/\1,\2,\3,\4/p' "$out/deposit.box.yaml")
"$build/gb_jam" "$out/deposit.csv" --box "$box" --porosity 0.15 --kn 1e8 --tol 1 --out "$out/jammed.csv" > "$out/jammed.box"
cat > "$out/scene.yaml" <<YAML
gembem: 1
units: {length: cm, force: dyn}
materials:
  grain_grain: {kn: 1.0e8, kt: 7.0e7, friction_deg: 25}
  grain_wall:  {kn: 1.0e8, kt: 7.0e7, friction_deg: 0}
grains: {file: jammed.csv}
$(cat "$out/jammed.box")
solver: {accuracy: 100, max_iterations: 100000}
loading:  # test_jammed_steps drives the walls itself
  - isotropic: {stress: 1.0e6, steps: 1}
YAML
