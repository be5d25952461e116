#!/usr/bin/env bash
# 1. A run that stops at its iteration cap: exit status 3, a message naming the step and how far it
#    is from convergence, steps.csv and the state of the completed steps kept.
# 2. Preparation and shear as two runs (the second starts from the first one's state.yaml) give the
#    same shear curve as one run, to 1e-12.
set -u
gembem=$1; root=$(cd "$(dirname "$0")/../.." && pwd)
source "$root/tests/csv.sh"
source "$root/tests/scene.sh"
out=$(mktemp -d); fail=0
case1=$root/validation/three_discs/case1.yaml

# 1. Non-convergence: the three discs with a cap of 5 iterations per step.
msg=$("$gembem" run "$root/tests/cli/scenes/capped.yaml" -o "$out/capped" 2>&1 >/dev/null); code=$?
echo "capped run: exit $code: $msg"
[ $code -eq 3 ] || { echo "FAIL: exit status $code, expected 3"; fail=1; }
case "$msg" in *"step 1 (stage 1 'isotropic', step 1 of 10) did not converge in 5 iterations: largest fixing force"*) ;;
  *) echo "FAIL: message does not name the step and the residual"; fail=1;; esac
rows=$(wc -l < "$out/capped/steps.csv")
[ "$rows" -eq 2 ] || { echo "FAIL: steps.csv has $rows lines, expected the header and step 0"; fail=1; }
[ -f "$out/capped/state.yaml" ] || { echo "FAIL: no state.yaml of the completed steps"; fail=1; }
grep -q "status: not converged" "$out/capped/run_info.yaml" || { echo "FAIL: run_info.yaml does not say not converged"; fail=1; }

# 2. Restart: one run, then the same in two runs.
"$gembem" run "$case1" -o "$out/whole" --quiet || fail=1
# case1's loading: 0 isotropic, 1 shear_mean_stress; its output: snapshot_steps only
no_snapshots=(--delete output.snapshot_steps --add output.snapshot_every=0)
scene_edit "$case1" -o "$out/prep.yaml" --delete loading.1 "${no_snapshots[@]}"
"$gembem" run "$out/prep.yaml" -o "$out/prep" --quiet || fail=1
scene_edit "$case1" -o "$out/shear.yaml" --delete grains --delete box --delete loading.0 "${no_snapshots[@]}" \
  --add initial_state=prep/state.yaml
"$gembem" run "$out/shear.yaml" -o "$out/shear" --quiet || fail=1
# Compare the stress ratio of the last 100 rows (the shear) of both.
shear_curve() { csv_awk '{ print $col("e1_minus_e2") "," $col("stress_ratio") }' "$1" | tail -n 100; }
shear_curve "$out/whole/steps.csv" > "$out/a"
shear_curve "$out/shear/steps.csv" > "$out/b"
/usr/bin/env awk -F, 'NR==FNR {r[FNR]=$2; g[FNR]=$1; next}
  { d = $2 - r[FNR]; if (d < 0) d = -d; if (d > m) m = d; dg = $1 - g[FNR]; if (dg < 0) dg = -dg; if (dg > mg) mg = dg }
  END { printf "restart: largest difference in stress ratio %.3g, in e1-e2 %.3g over %d steps\n", m, mg, FNR;
        exit (m > 1e-12 || mg > 1e-12 || FNR != 100) }' "$out/a" "$out/b" || { echo "FAIL: the restarted shear differs"; fail=1; }
rm -rf "$out"
[ $fail -eq 0 ] && echo "2 passed, 0 failed" || echo "0 passed, 1 failed"
exit $fail
