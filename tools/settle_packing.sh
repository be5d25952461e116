#!/usr/bin/env bash
# A random deposit of the paper's three sizes (diameters 0.6, 0.9, 1.2 cm, equal area per size) by
# gb_packgen, every disc resting on others, its radii enlarged by 1e-9 so that the touching pairs
# are contacts (with forces of 1e-9 kn r), and a scene that lets it settle under its own weight
# between fixed walls (Table 3 constants: kn, kt = 1e8, 7e7 dyn/cm, phi = 25 deg; density 2.65
# g/cm^3, g = 981 cm/s^2), run by build/bench_settle: a known limit of docs/limits.md (the global solver
# does not converge on it, the reference iteration does).
#   [KEEP=1] tools/settle_packing.sh BUILD_DIR OUT_DIR N SEED
# Writes OUT_DIR/deposit.csv (+ .box.yaml), settle.csv and scene.yaml; KEEP=1 reuses settle.csv.
set -euo pipefail
source "$(dirname "$0")/lib.sh"
build=$1 out=$2 n=$3 seed=$4
mkdir -p "$out"
if [ "${KEEP:-0}" != 1 ] || [ ! -s "$out/settle.csv" ]; then
  "$build/gb_packgen" --n "$n" --diameters 0.6,0.9,1.2 --seed "$seed" --out "$out/deposit.csv" >/dev/null
  awk -F, 'NR == 1 { print; next } { printf "%.17g,%.17g,%.17g\n", $1, $2, $3 * (1 + 1e-9) }' \
    "$out/deposit.csv" > "$out/settle.csv.part"
  mv "$out/settle.csv.part" "$out/settle.csv"
fi
cat > "$out/scene.yaml" <<YAML
$(table3_scene_head settle.csv)
$(grep '^box:' "$out/deposit.box.yaml")
body_force: {gravity: [0, -981], density: 2.65}
solver: {accuracy: 100, max_iterations: 2000000}
loading:  # not used by bench_settle, which holds the walls
  - isotropic: {stress: 1.0e5, steps: 1}
YAML
