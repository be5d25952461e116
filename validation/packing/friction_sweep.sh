#!/usr/bin/env bash
# The packings of box_growth.yaml's grains grown to a mean stress of 1e-4 kn with friction while
# packing (pack.friction_deg), against the frictionless one: the solid fraction (of the box, and in
# bulk.py's window 8 cm from the walls), the coordination (with and without rattlers) and the
# rattlers, a Markdown row per angle (README.md, "With friction"). 1e4 discs in a 77.2 cm box, the
# grains' friction angle the larger of the scene's 25 degrees and the packing's, seed 1.
#   validation/packing/friction_sweep.sh [BUILD_DIR] [ANGLE ...]      (0 5 10 15 25 45 80 by default)
# Runs in runs/friction_sweep/fF (kept). COUNT=n and SIDE=s for another size (1e3: 1000 and 24.4,
# whose window is 4 cm from the walls: WINDOW=4); THREADS=n (default 2) the solver.threads of FIRE
# (the same packing on any number).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd); root=$(cd "$here/../.." && pwd)
build=$root/${1:-build}; shift || true
angles=${*:-0 5 10 15 25 45 80}
count=${COUNT:-10000}; side=${SIDE:-77.2}; window=${WINDOW:-8}
source "$root/tests/scene.sh"
echo "machine: $(nproc --all) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); $(date -u '+%Y-%m-%d %H:%M'); $count discs, box $side cm, seed 1"
echo
echo "| friction while packing [deg] (mu) | solid fraction: box (bulk window) | coordination (without rattlers) | rattlers | FIRE iterations | seconds |"
echo "|---:|---|---|---:|---:|---:|"
for f in $angles; do
  d=$root/runs/friction_sweep/f$f${COUNT:+_n$count}
  mkdir -p "$d"
  grain=$(awk -v f="$f" 'BEGIN { print (f > 25 ? f : 25) }')
  scene_edit "$here/box_growth.yaml" -o "$d/scene.yaml" --set pack.count="$count" --set box.right="$side" \
    --set box.top="$side" --set materials.grain_grain.friction_deg="$grain" --add pack.friction_deg="$f" \
    --add solver.threads="${THREADS:-2}"
  "$build/gembem" pack "$d/scene.yaml" -o "$d/out" --overwrite --quiet
  hi=$(awk -v s="$side" -v w="$window" 'BEGIN { print s - w }')
  bulk=$(/usr/bin/python3 "$here/bulk.py" "$d/out" "$window" "$hi" "$window" "$hi" | sed 's/.*solid fraction \([0-9.]*\).*/\1/')
  /usr/bin/python3 - "$d/out/pack_info.yaml" "$f" "$bulk" <<'PY'
import math, sys
info = {}
for line in open(sys.argv[1]):
    if ":" in line and not line.startswith("#"):
        k, v = line.split(":", 1)
        info[k.strip()] = v.split("#")[0].strip()
its = sum(float(x.split(":")[1]) for x in info["fire_iterations"].strip("{}").split(","))
sec = info["seconds"].split("total:")[1].strip(" }")
f = float(sys.argv[2])
print(f"| {sys.argv[2]} ({math.tan(math.radians(f)):.3g}) | {float(info['solid_fraction']):.4f} ({sys.argv[3]}) | "
      f"{float(info['coordination']):.3f} ({float(info['coordination_without_rattlers']):.3f}) | {info['rattlers']} | "
      f"{its:.0f} | {float(sec):.1f} |")
PY
done
