#!/usr/bin/env bash
# tools/mirrored_packing.sh: a jammed packing (walls of 2 kn) mirrored into 2 x 2 copies is in
# equilibrium as it stands: gembem's fixing forces (bench_jammed with no load step and no
# iteration allowed) stay below a = 5 dyn, where gembem pack's FIRE left every disc below 1 dyn. Control: with
# the walls of the copies at kn, the discs against the outer walls lose half their wall force
# (kn d ~ 1e5 dyn) and the same check fails.
#   test_mirrored_packing.sh BUILD_DIR WORK_DIR
set -u
build=$1 work=$2
root=$(cd "$(dirname "$0")/../.." && pwd)
source "$root/tests/scene.sh"
rm -rf "$work"
"$root/tools/mirrored_packing.sh" "$build" "$work" 300 3 1 2 || { echo "FAIL mirrored_packing.sh"; exit 1; }
n=$(($(wc -l < "$work/jammed.csv") - 1))
[ "$n" = 1200 ] || { echo "FAIL $n discs, expected 1200"; exit 1; }
fail=0
row=$("$build/bench_jammed" "$work/scene.yaml" 0 cholmod 0 5 2>&1)
if [ $? -eq 0 ] && grep -q '| 0 (' <<< "$row"; then echo "ok   1200 mirrored discs in equilibrium within 5 dyn"
else echo "FAIL the mirrored packing is not in equilibrium: $row"; fail=1; fi
scene_edit "$work/scene.yaml" -o "$work/scene_soft_walls.yaml" --set materials.grain_wall.kn=1.0e8   # of 2.0e8
row=$("$build/bench_jammed" "$work/scene_soft_walls.yaml" 0 cholmod 0 5 2>&1)
if [ $? -eq 3 ]; then echo "ok   control: walls of kn leave it out of equilibrium ($(grep -o 'largest fixing force.*' <<< "$row"))"
else echo "FAIL control: walls of kn should leave it out of equilibrium: $row"; fail=1; fi
exit $fail
