#!/usr/bin/env bash
# A load step's work is bounded whatever solver.max_iterations says, and a long step says so as it
# runs (src/solver/relax.c's stall window, src/gem/watch.c). The three discs of
# validation/three_discs/case1.yaml, their isotropic stage in one step:
#  1. alpha 1.5 makes the reference iteration unstable (each grain moved 1.5 times its own
#     balancing move while its neighbours move too: the largest force wanders between about 1e4 and
#     3e5 dyn and never reaches a = 100): with max_iterations 2e9 (hours of iterations) the step
#     must stall, be cut back, stall again and fail with exit 3, "stalled", in seconds; the hint
#     must not ask for more iterations.
#  2. The same with solver.max_step_seconds 0.001: exit 3, "reached solver.max_step_seconds", and
#     no cut-back (a sub-step would only take longer).
#  3. With the progress hook at 0.02 s (GB_TEST_PROGRESS_SECONDS), the unstable step prints its
#     progress lines on stderr, also when stderr is not a terminal.
#  4. The stable iteration (alpha 0.75) converges: steps.csv's stop is "converged" at every step
#     and sweeps_per_iteration 0 (the reference iteration has no smoother).
set -u
gembem=$1; root=$(cd "$(dirname "$0")/../.." && pwd)
source "$root/tests/csv.sh"
source "$root/tests/scene.sh"
source "$root/tools/lib.sh"
gb_test_begin
scene() { # OUT.yaml ALPHA [EXTRA scene_edit arguments]: case1's isotropic stage (loading 0) in one step
  local o=$1 a=$2; shift 2
  scene_edit "$root/validation/three_discs/case1.yaml" -o "$o" --delete loading.1 --set loading.0.isotropic.steps=1 \
    --delete output.snapshot_steps --add output.snapshot_every=0 --set solver.alpha="$a" \
    --set solver.max_iterations=2000000000 "$@"
}
status() { awk '/^status:/ { print $2, $3 }' "$1/run_info.yaml"; }

scene "$out/unstable.yaml" 1.5
start=$(date +%s)
msg=$(GB_TEST_PROGRESS_SECONDS=0.02 "$gembem" run "$out/unstable.yaml" -o "$out/unstable" 2>&1 >/dev/null); code=$?
took=$(( $(date +%s) - start ))
[ $code -eq 3 ] && ok "unstable: exit 3 after $took s" || bad "unstable: exit $code, expected 3: $msg"
[[ $msg =~ "stalled (its largest fixing force stopped falling)" ]] && ok "unstable: says it stalled" \
  || bad "unstable: no stall in: $msg"
[[ $msg =~ "nor in sub-steps down to 1/16" ]] && ok "unstable: cut back to 1/16 first" || bad "unstable: not cut back: $msg"
[[ $msg =~ "max_iterations" ]] && bad "unstable: asks for more iterations: $msg" || ok "unstable: no advice of more iterations"
[ "$(status "$out/unstable")" = "not converged" ] && ok "unstable: run_info.yaml says not converged" \
  || bad "unstable: status $(status "$out/unstable")"
n=$(grep -c "gembem: step 1 (1 of 1 in its stage) has run .* iterations, 0 smoother steps, largest fixing force" <<<"$msg")
[ "$n" -ge 1 ] && ok "unstable: $n progress lines" || bad "unstable: no progress line in: $msg"

scene "$out/timed.yaml" 1.5 --add solver.max_step_seconds=0.001
msg=$("$gembem" run "$out/timed.yaml" -o "$out/timed" 2>&1 >/dev/null); code=$?
[ $code -eq 3 ] && ok "time limit: exit 3" || bad "time limit: exit $code, expected 3: $msg"
[[ $msg =~ "reached solver.max_step_seconds (0.001 s)" ]] && ok "time limit: named" || bad "time limit: $msg"
[[ $msg =~ "sub-steps" ]] && bad "time limit: cut back: $msg" || ok "time limit: no cut-back"

scene "$out/stable.yaml" 0.75 --set loading.0.isotropic.steps=3
if "$gembem" run "$out/stable.yaml" -o "$out/stable" --quiet; then
  stops=$(csv_awk 'NR > 1 { print $col("stop") }' "$out/stable/steps.csv" | sort -u | tr '\n' ' ')
  spi=$(csv_awk 'NR > 1 { print $col("sweeps_per_iteration") }' "$out/stable/steps.csv" | sort -u | tr '\n' ' ')
  [ "$stops" = "converged " ] && ok "stable: stop converged at every step" || bad "stable: stop '$stops'"
  [ "$spi" = "0 " ] && ok "stable: no smoother steps" || bad "stable: sweeps_per_iteration '$spi'"
else bad "stable: did not converge"; fi

gb_test_end
