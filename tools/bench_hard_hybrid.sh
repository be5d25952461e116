#!/usr/bin/env bash
# The hard hybrid cases of tools/bench/hard_hybrid/ (its README says what each is): packs each
# case's grains once (cached by the pack scene's contents), runs the case under `timeout`, and
# prints per step the work of the global solver (iterations, smoother sweeps, factorisations),
# each step's ratio to the run's median step, whether the run completed, and how the largest
# fixing force went in the costliest step (history.csv). Counts do not depend on the machine's
# load; seconds do.
#   tools/bench_hard_hybrid.sh BUILD_DIR [CASE...]       (default: every case)
# Environment: OUT (default runs/hard_hybrid), TIMEOUT per case (default 20m, as timeout(1)
# reads it), NICE (default 10). A case's run directory is OUT/runs/CASE (replaced on each run);
# the packings are OUT/packs/NAME.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
bench=$root/tools/bench/hard_hybrid
if [ $# -lt 1 ] || [ ! -x "$1/gembem" ]; then
  echo "usage: $0 BUILD_DIR [CASE...]   (BUILD_DIR holds the gembem executable)" >&2
  echo "cases: $(cd "$bench" && ls *.yaml | grep -v '^pack_' | sed 's/\.yaml$//' | tr '\n' ' ')" >&2
  exit 2
fi
gembem=$(cd "$1" && pwd)/gembem; shift
out=${OUT:-$root/runs/hard_hybrid}
limit=${TIMEOUT:-20m}
nice_level=${NICE:-10}
if [ $# -eq 0 ]; then
  set -- $(cd "$bench" && ls *.yaml | grep -v '^pack_' | sed 's/\.yaml$//')
fi
mkdir -p "$out/packs" "$out/scenes" "$out/runs" || exit 1

# Packs tools/bench/hard_hybrid/pack_NAME.yaml into OUT/packs/NAME unless the packing there was
# made from the same pack scene (its copy, scene.yaml).
pack() {
  local dir=$out/packs/$1 scene=$bench/pack_$1.yaml
  [ -f "$scene" ] || { echo "no pack scene $scene" >&2; return 1; }
  if [ -f "$dir/state.yaml" ] && cmp -s "$scene" "$dir/scene.yaml"; then return 0; fi
  rm -rf "$dir"
  nice -n "$nice_level" "$gembem" pack "$scene" -o "$dir" || return 1
}

status=0
for case in "$@"; do
  scene=$bench/$case.yaml
  [ -f "$scene" ] || { echo "no case $case ($scene)" >&2; status=2; continue; }
  # The packing the scene starts from: its `initial_state: packs/NAME/state.yaml`.
  name=$(sed -n 's|^initial_state: *packs/\([A-Za-z0-9_]*\)/state.yaml.*|\1|p' "$scene")
  [ -n "$name" ] || { echo "$scene: no 'initial_state: packs/NAME/state.yaml'" >&2; status=2; continue; }
  pack "$name" || { echo "$case: packing $name failed" >&2; status=1; continue; }
  # The run's copy of the scene, with the mesh and the packing by absolute paths.
  copy=$out/scenes/$case.yaml
  sed -e "s|^initial_state: *packs/|initial_state: $out/packs/|" \
      -e "s|^\(  mesh: *\)\([^ ]*\)|\1$bench/\2|" "$scene" > "$copy" || exit 1
  run=$out/runs/$case
  rm -rf "$run"
  echo "== $case (timeout $limit): $gembem run $copy -o $run"
  nice -n "$nice_level" timeout "$limit" "$gembem" run "$copy" -o "$run" --quiet
  code=$?
  /usr/bin/python3 "$root/tools/bench_hard_hybrid_table.py" "$run" --exit "$code" || status=1
done
exit $status
