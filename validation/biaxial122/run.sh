#!/usr/bin/env bash
# Validation B: the 122-disc biaxial test (Kishino 1989, section 4). For each seed: a packing from
# tools/packgen (diameters 0.6, 0.9, 1.2 cm, equal area per size, densest deposition), the scene
# from scene.yaml.in, a gembem run, and the figures; then the statistics over all seeds.
#   validation/biaxial122/run.sh [BUILD_DIR] [SEED ...]      (default: build, seeds 1 2 3 4 5)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd); root=$(cd "$here/../.." && pwd)
build=$root/${1:-build}; shift || true
seeds=${*:-1 2 3 4 5}
out=$root/runs/biaxial122
mkdir -p "$out"
for s in $seeds; do
  d=$out/seed$s; mkdir -p "$d"
  "$build/gb_packgen" --n 122 --diameters 0.6,0.9,1.2 --seed "$s" --out "$d/grains.csv" >/dev/null
  sed -e "s|@GRAINS@|grains.csv|; s|@SEED@|$s|" -e "s|@BOX@|$(grep '^box:' "$d/grains.box.yaml")|" \
      "$here/scene.yaml.in" > "$d/scene.yaml"
  start=$(date +%s.%N)
  "$build/gembem" run "$d/scene.yaml" -o "$d/run" --overwrite --quiet
  echo "seed $s: $(echo "$(date +%s.%N) - $start" | bc) s"
done
/usr/bin/python3 "$here/figures.py" "$out/seed$(echo $seeds | cut -d' ' -f1)/run" "$here/figures"
/usr/bin/python3 "$here/stats.py" $(for s in $seeds; do echo "$out/seed$s/run"; done) | tee "$here/stats.md"
