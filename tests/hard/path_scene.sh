# Sourced by check_equilibrium.sh and check_equilibrium_rolling.sh: the independent checkers, the
# verdict counters, and the scene of their 4-step oedometric path from the jammed fixture.
check=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)/tools/check_equilibrium.py
steperr=$(dirname "$check")/check_step_error.py
fails=0
ok() { echo "ok: $*"; }
bad() { echo "FAIL: $*"; fails=$((fails + 1)); }
# path_scene METHOD JAMMED_DIR OUT.yaml SOLVER_EXTRA OUTPUT_LINES [SED_ARGS ...]: the fixture's
# scene with METHOD's solver (reference, global or line_search) plus SOLVER_EXTRA keys, SED_ARGS
# applied, and the path, then OUTPUT_LINES.
path_scene() {
  local method=$1 jammed=$2 file=$3 extra=$4 output=$5 solver
  shift 5
  solver="method: $method"; [ "$method" = line_search ] && solver="method: global, newton: line_search"
  sed -e "s|^grains: {file: jammed.csv}|grains: {file: $jammed/jammed.csv}|" \
      -e "s|^solver: .*|solver: {$solver, accuracy: 100, max_iterations: 2000000$extra}|" \
      "$@" -e '/^loading:/,$d' "$jammed/scene.yaml" > "$file"
  printf 'loading:\n  - strain: {de1: 0.0005, de2: 0, steps: 4}\n%s' "$output" >> "$file"
}
