# Sourced by check_equilibrium.sh and check_equilibrium_rolling.sh: the independent checkers, the
# verdict counters, and the scene of their 4-step oedometric path from the jammed fixture.
source "$(dirname "${BASH_SOURCE[0]}")/../scene.sh"
check=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)/tools/check_equilibrium.py
steperr=$(dirname "$check")/check_step_error.py
fails=0
ok() { echo "ok: $*"; }
bad() { echo "FAIL: $*"; fails=$((fails + 1)); }
# path_scene METHOD JAMMED_DIR OUT.yaml [EDIT ...]: the fixture's scene (its grains file named
# absolute) with METHOD's solver (reference, global or line_search) and the path, then the
# scene_edit EDITs (e.g. --add solver.history=true).
path_scene() {
  local method=$1 jammed=$2 file=$3 solver
  shift 3
  solver="method: $method"; [ "$method" = line_search ] && solver="method: global, newton: line_search"
  scene_edit "$jammed/scene.yaml" -o "$file" --set "solver={$solver, accuracy: 100, max_iterations: 2000000}" \
    --set 'loading=[{strain: {de1: 0.0005, de2: 0, steps: 4}}]' "$@"
}
