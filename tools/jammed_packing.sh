#!/usr/bin/env bash
# A jammed packing of the paper's three sizes (diameters 0.6, 0.9, 1.2 cm, equal area per size):
# gb_packgen's densest deposition, shrunk to porosity 0.15 and relaxed frictionless with the walls
# fixed by gb_jam (FIRE) to |F| <= TOL dyn per disc, an equilibrium that friction keeps; and a scene
# that starts from it (Table 3 constants: kn, kt = 1e8, 7e7 dyn/cm, phi = 25 deg, a = 100 dyn).
# Used by tools/bench_gem.sh and the ctest fixture of tests/hard/test_jammed_steps.
#   [KEEP=1] [WALL_KN=1e8] tools/jammed_packing.sh BUILD_DIR OUT_DIR N SEED TOL
# Writes OUT_DIR/deposit.csv (+ .box.yaml), jammed.csv, jammed.box (the scene's box line),
# jammed.log (gb_jam's summary) and scene.yaml. KEEP=1 reuses an existing jammed.csv (1e5 discs
# take 20-50 minutes). WALL_KN: the walls' stiffness (2e8 for tools/mirrored_packing.sh).
set -euo pipefail
build=$1 out=$2 n=$3 seed=$4 tol=$5 wall_kn=${WALL_KN:-1.0e8}
mkdir -p "$out"
if [ "${KEEP:-0}" != 1 ] || [ ! -s "$out/jammed.csv" ] || [ ! -s "$out/jammed.box" ]; then
  "$build/gb_packgen" --n "$n" --diameters 0.6,0.9,1.2 --seed "$seed" --out "$out/deposit.csv" >/dev/null
  box=$(sed -n 's/^box: {left: \([^,]*\), right: \([^,]*\), bottom: \([^,]*\), top: \([^}]*\)}$/\1,\2,\3,\4/p' \
        "$out/deposit.box.yaml")
  "$build/gb_jam" "$out/deposit.csv" --box "$box" --porosity 0.15 --kn 1e8 --wall-kn "$wall_kn" --tol "$tol" \
    --out "$out/jammed.csv" > "$out/jammed.box" 2> "$out/jammed.log"
fi
cat > "$out/scene.yaml" <<YAML
gembem: 1
units: {length: cm, force: dyn}
materials:
  grain_grain: {kn: 1.0e8, kt: 7.0e7, friction_deg: 25}
  grain_wall:  {kn: $wall_kn, kt: 7.0e7, friction_deg: 0}
grains: {file: jammed.csv}
$(cat "$out/jammed.box")
solver: {accuracy: 100, max_iterations: 2000000}
loading:  # not used by bench_jammed and test_jammed_steps, which drive the walls themselves
  - isotropic: {stress: 1.5e5, steps: 1}
YAML
