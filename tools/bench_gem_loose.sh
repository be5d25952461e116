#!/usr/bin/env bash
# The first benchmark protocol (not a test), kept because docs/benchmarks.md quotes it: random packings of the paper's three sizes
# (Table 3: diameters 0.6, 0.9, 1.2 cm, equal area per size, kn, kt = 1e8, 7e7 dyn/cm, phi = 25 deg,
# a = 100 dyn) made by gb_packgen at its densest deposition (porosity about 0.27, not jammed),
# prepared by isotropic stress control at s0/2 (at most PREP_CAP iterations), then STEPS load steps
# to s0 = 1.5e5 dyn/cm. Prints, per size: contacts, preparation iterations, iterations per load
# step, seconds per iteration, and nanoseconds per contact and iteration.
#   [SOLVER=reference|cholmod|umfpack] tools/bench_gem_loose.sh [BUILD_DIR] [N ...]   (default: build, 1000 10000 100000)
set -euo pipefail
source "$(dirname "$0")/lib.sh"
bench_args "$@"
mkdir -p "$out"
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); $(date -u +%Y-%m-%d)"
echo "threads: OMP_NUM_THREADS=${OMP_NUM_THREADS:-unset} (the reference iteration is single-threaded)"
printf "| solver | N | contacts | preparation iterations | iterations per load step | s per iteration | ns per contact-iteration | total s |\n|---|---|---|---|---|---|---|---|\n"
for n in $sizes; do
  d=$out/n$n; mkdir -p "$d"
  "$build/gb_packgen" --n "$n" --diameters 0.6,0.9,1.2 --seed 1 --out "$d/grains.csv" >/dev/null
  cat > "$d/scene.yaml" <<YAML
$(table3_scene_head grains.csv)
$(grep '^box:' "$d/grains.csv.box.yaml" 2>/dev/null || grep '^box:' "$d/grains.box.yaml")
solver: {accuracy: 100, max_iterations: 1000000}
loading:  # not used by bench_gem, which drives the stress itself
  - isotropic: {stress: 1.5e5, steps: $steps}
YAML
  # Preparation cap: a budget of about 3e9 contact-iterations per size.
  cap=${PREP_CAP:-$((3000000000 / (2 * n)))}
  "$build/bench_gem" "$d/scene.yaml" 1.5e5 "$cap" "$steps" "${SOLVER:-reference}" | tail -n 1
done
