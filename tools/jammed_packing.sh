#!/usr/bin/env bash
# A jammed packing of the paper's three sizes (diameters 0.6, 0.9, 1.2 cm, equal area per size):
# `gembem pack` grows N discs in a square box to porosity 0.15 (solid fraction 0.85, past jamming),
# frictionless by FIRE to |F| <= TOL dyn per disc, then gembem's own solver with friction
# (docs/packing.md); and a scene that starts from it (Table 3 constants: kn, kt = 1e8, 7e7 dyn/cm,
# phi = 25 deg, a = 100 dyn). Used by tools/bench_gem.sh, tools/bench_scaling.sh,
# tools/speed_vs_error.py and the ctest fixture of tests/hard.
#   [KEEP=1] [WALL_KN=1e8] tools/jammed_packing.sh BUILD_DIR OUT_DIR N SEED TOL
# Writes OUT_DIR/pack.yaml and pack/ (gembem pack's scene and directory), jammed.csv (x,y,r),
# jammed.box (the scene's box line), jammed.log (a summary with the walls' stresses, measured by
# gembem run from the state) and scene.yaml. KEEP=1 reuses an existing jammed.csv. WALL_KN: the
# walls' stiffness (2e8 for tools/mirrored_packing.sh).
set -euo pipefail
build=$1 out=$2 n=$3 seed=$4 tol=$5 wall_kn=${WALL_KN:-1.0e8}
mkdir -p "$out"
header() { # the scenes' first lines: units and the Table 3 materials
  printf 'gembem: 1\nunits: {length: cm, force: dyn}\nmaterials:\n'
  printf '  grain_grain: {kn: 1.0e8, kt: 7.0e7, friction_deg: 25}\n'
  printf '  grain_wall:  {kn: %s, kt: 7.0e7, friction_deg: 0}\n' "$wall_kn"
}
if [ "${KEEP:-0}" != 1 ] || [ ! -s "$out/jammed.csv" ] || [ ! -s "$out/jammed.box" ]; then
  # the box holds the discs at solid fraction 0.85: the mean disc area of the mix is
  # 1 / sum over sizes of (1/3) / (pi r^2)
  side=$(awk -v n="$n" 'BEGIN { pi = atan2(0, -1); s = 0; split("0.3 0.45 0.6", r, " ");
                                for (k = 1; k <= 3; k++) s += 1 / (3 * pi * r[k] * r[k]);
                                printf "%.17g", sqrt(n / s / 0.85) }')
  box="{left: 0, right: $side, bottom: 0, top: $side}"
  { header; cat <<YAML; } > "$out/pack.yaml"
box: $box
solver: {accuracy: $tol}   # FIRE settles to it, gembem's solver checks it
pack:
  protocol: growth
  seed: $seed
  sizes: {diameters: [0.6, 0.9, 1.2]}
  count: $n
  solid_fraction: 0.85
YAML
  "$build/gembem" pack "$out/pack.yaml" -o "$out/pack" --overwrite --quiet
  awk -F, 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; print "x,y,r"; next }
           { print $c["x"] "," $c["y"] "," $c["r"] }' "$out/pack/state_grains.csv" > "$out/jammed.csv.part"
  mv "$out/jammed.csv.part" "$out/jammed.csv"
  echo "box: $box" > "$out/jammed.box"
  # the walls' stresses, gembem's own measure of the state (step 0 of a held relax)
  { header; cat <<YAML; } > "$out/walls.yaml"
initial_state: pack/state.yaml
solver: {accuracy: 100}
loading:
  - relax: {steps: 1}
YAML
  "$build/gembem" run "$out/walls.yaml" -o "$out/walls" --overwrite --quiet 2> "$out/walls.err"
  info() { sed -n "s/^$1: \([^#]*\).*/\1/p" "$out/pack/pack_info.yaml" | sed 's/ *$//'; }
  read -r s1 s2 < <(awk -F, 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
                              NR == 2 { print $c["s1"], $c["s2"] }' "$out/walls/steps.csv")
  echo "gembem pack: $n discs, porosity $(info porosity), FIRE iterations $(info fire_iterations)," \
       "largest fixing force $(info max_fixing_force), coordination $(info coordination)," \
       "wall stresses s_x $s1 s_y $s2" > "$out/jammed.log"
fi
{ header; cat <<YAML; } > "$out/scene.yaml"
grains: {file: jammed.csv}
$(cat "$out/jammed.box")
solver: {accuracy: 100, max_iterations: 2000000}
loading:  # not used by bench_jammed and test_jammed_steps, which drive the walls themselves
  - isotropic: {stress: 1.5e5, steps: 1}
YAML
