#!/usr/bin/env bash
# Load-step cut-backs (solver.cutbacks, src/gem/sim.c), against the same loading split by hand.
# The three discs of validation/three_discs/case1.yaml, isotropic compression to 1.5e5 dyn/cm^2 with
# the reference iteration: in one step it takes 40 iterations, in two steps 36 + 38, in four 33-34.
#  1. One step with a cap of 39 iterations: cut into halves, it must end where the two-step run ends
#     (to 1e-12: the same computation once the failed attempt is undone), report 2 sub-steps and
#     39 + 36 + 38 iterations (the failed attempt counted).
#  2. A cap of 35: halves fail too, quarters converge: the four-step run's end, 4 sub-steps.
#  3. cutbacks: 0 stops at the first failure; cutbacks: 1 with a cap of 35 stops too, and says
#     how fine the sub-steps it tried were.
set -u
gembem=$1; root=$(cd "$(dirname "$0")/../.." && pwd)
source "$root/tests/csv.sh"
source "$root/tests/scene.sh"
source "$root/tools/lib.sh"
gb_test_begin
scene() { # OUT.yaml STEPS CAP [CUTBACKS]: case1's isotropic stage (loading 0) alone
  scene_edit "$root/validation/three_discs/case1.yaml" -o "$1" --delete loading.1 --set loading.0.isotropic.steps="$2" \
    --delete output.snapshot_steps --add output.snapshot_every=0 --set solver.max_iterations="$3" \
    ${4:+--add solver.cutbacks="$4"}
}
last() { csv_awk -v n="$2" '{ v = $col(n) } END { print v }' "$1/steps.csv"; } # RUN COLUMN: its value in the last row
same_end() { # RUN_A RUN_B LABEL: width and height of the last rows to 1e-12 relative
  awk -v a="$(last "$1" width) $(last "$1" height)" -v b="$(last "$2" width) $(last "$2" height)" -v l="$3" '
    BEGIN { split(a, x, " "); split(b, y, " ");
    d = 0; for (c = 1; c <= 2; c++) { e = (x[c] - y[c]) / y[c]; if (e < 0) e = -e; if (e > d) d = e }
    printf "%s: width and height differ by %.3g (relative)\n", l, d; exit d > 1e-12 }'
}
for s in "2 100000" "4 100000"; do scene "$out/split${s%% *}.yaml" $s; "$gembem" run "$out/split${s%% *}.yaml" -o "$out/split${s%% *}" --quiet || bad "split run $s"; done
its2=$(csv_awk '{ print $col("iterations") }' "$out/split2/steps.csv" | tail -n 2 | awk '{ s += $1 } END { print s }')

scene "$out/cap39.yaml" 1 39
if "$gembem" run "$out/cap39.yaml" -o "$out/cap39" --quiet; then
  r=$(last "$out/cap39" substeps); i=$(last "$out/cap39" iterations)
  [ "$r" = 2 ] && ok "cap 39: 2 sub-steps" || bad "cap 39: $r sub-steps, expected 2"
  [ "$i" = $((39 + its2)) ] && ok "cap 39: $i iterations = 39 + the two-step run's $its2" \
    || bad "cap 39: $i iterations, expected 39 + $its2"
  same_end "$out/cap39" "$out/split2" "cap 39 against two steps" && ok "cap 39 ends where two steps end" || bad "cap 39 end"
else bad "cap 39: the cut-back step did not converge"; fi

scene "$out/cap35.yaml" 1 35
if "$gembem" run "$out/cap35.yaml" -o "$out/cap35" --quiet; then
  r=$(last "$out/cap35" substeps)
  [ "$r" = 4 ] && ok "cap 35: 4 sub-steps" || bad "cap 35: $r sub-steps, expected 4"
  same_end "$out/cap35" "$out/split4" "cap 35 against four steps" && ok "cap 35 ends where four steps end" || bad "cap 35 end"
else bad "cap 35: the cut-back step did not converge"; fi

scene "$out/nocut.yaml" 1 39 0
msg=$("$gembem" run "$out/nocut.yaml" -o "$out/nocut" 2>&1 >/dev/null); code=$?
[ $code -eq 3 ] && ok "cutbacks 0: exit 3" || bad "cutbacks 0: exit $code, expected 3"
case "$msg" in *"did not converge in 39 iterations"*"(accuracy a = 100); the outputs hold the 0 completed steps"*)
  ok "cutbacks 0: no sub-step in the message";; *) bad "cutbacks 0: message: $msg";; esac
scene "$out/onecut.yaml" 1 35 1
msg=$("$gembem" run "$out/onecut.yaml" -o "$out/onecut" 2>&1 >/dev/null); code=$?
[ $code -eq 3 ] && ok "cutbacks 1, cap 35: exit 3" || bad "cutbacks 1, cap 35: exit $code, expected 3"
case "$msg" in *"nor in sub-steps down to 1/2 of the step; the outputs hold the 0 completed steps"*)
  ok "cutbacks 1: the message names the finest sub-step";; *) bad "cutbacks 1: message: $msg";; esac
gb_test_end
