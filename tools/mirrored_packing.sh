#!/usr/bin/env bash
# A packing of K x K N discs made from one of N (the 1e6 row of tools/bench_scaling.sh was made so
# when jamming 1e6 discs took days; `gembem pack` is faster, docs/packing.md): one jammed packing of N discs
# (tools/jammed_packing.sh, its walls twice as stiff as the contacts: WALL_KN = 2e8) mirrored
# across its walls into K x K copies. A disc that presses a wall by d (force 2 kn d) presses its
# mirror image by 2 d (force kn 2 d): the copies together are in equilibrium as the packing was,
# inside walls of the same stiffness. Random within a copy, mirror-periodic beyond it: a test of
# the solvers' cost at size K^2 N, not of how a larger random packing behaves.
#   [KEEP=1] tools/mirrored_packing.sh BUILD_DIR OUT_DIR N SEED TOL K
# Writes OUT_DIR/base/ (the jammed packing), OUT_DIR/jammed.csv, jammed.box and scene.yaml.
set -euo pipefail
build=$1 out=$2 n=$3 seed=$4 tol=$5 k=$6
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
WALL_KN=2.0e8 "$root/tools/jammed_packing.sh" "$build" "$out/base" "$n" "$seed" "$tol"
read -r L R B T < <(sed -n 's/^box: {left: \([^,]*\), right: \([^,]*\), bottom: \([^,]*\), top: \([^}]*\)}$/\1 \2 \3 \4/p' \
  "$out/base/jammed.box")
awk -F, -v k="$k" -v L="$L" -v R="$R" -v B="$B" -v T="$T" '
  NR == 1 { print; next }
  { x[NR] = $1; y[NR] = $2; r[NR] = $3; m = NR }
  END {
    W = R - L; H = T - B
    for (cy = 0; cy < k; cy++) for (cx = 0; cx < k; cx++) for (i = 2; i <= m; i++) {
      X = cx % 2 ? L + (cx + 1) * W - (x[i] - L) : L + cx * W + (x[i] - L)
      Y = cy % 2 ? B + (cy + 1) * H - (y[i] - B) : B + cy * H + (y[i] - B)
      printf "%.17g,%.17g,%.17g\n", X, Y, r[i]
    }
  }' "$out/base/jammed.csv" > "$out/jammed.csv.part"
mv "$out/jammed.csv.part" "$out/jammed.csv"
awk -v k="$k" -v L="$L" -v R="$R" -v B="$B" -v T="$T" \
  'BEGIN { printf "box: {left: %.17g, right: %.17g, bottom: %.17g, top: %.17g}\n", L, L + k * (R - L), B, B + k * (T - B) }' \
  > "$out/jammed.box"
grep -v '^box:' "$out/base/scene.yaml" > "$out/scene.yaml"
cat "$out/jammed.box" >> "$out/scene.yaml"
