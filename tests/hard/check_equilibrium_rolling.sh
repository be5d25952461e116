#!/usr/bin/env bash
# Rolling resistance (docs/method.md section 3.1): the oedometric path of
# check_equilibrium.sh from the jammed fixture with rolling springs on every contact
# (kr = kt R*^2 of the mean R*, eta 0.1), with each solver (reference, global, global line search).
#  - tools/check_equilibrium.py recomputes every grain's force and moment from the positions, the
#    stored tangential forces and the stored rolling moments (the contacts file's column mr) and
#    checks the rolling limit |mr| <= eta R* pn; tools/check_step_error.py recomputes steps.csv's
#    error columns with the moments;
#  - the moments matter: some are nonzero, some at their limit, and the run's stresses differ from
#    the same path without rolling;
#  - negative controls: a moment changed by 500 dyn cm (the grains' moment balance fails), a moment past
#    its limit (the limit check fails);
#  - the state is read back exactly: a `relax` stage from it ends where it starts, mr unchanged
#    to the last digit; and a run killed and resumed from its checkpoint ends byte for byte as the
#    run that was not.
#   check_equilibrium_rolling.sh GEMBEM JAMMED_DIR OUT_DIR
set -euo pipefail
gembem=$1 jammed=$2 out=$3
source "$(dirname "$0")/path_scene.sh"
source "$(dirname "$0")/../csv.sh"
rm -rf "$out"; mkdir -p "$out"
rolling="{kr: 2.5e6, eta: 0.1}"
for method in reference global line_search; do
  path_scene $method "$jammed" "$out/$method.yaml" \
    --add "materials.grain_grain.rolling=$rolling" --add "materials.grain_wall.rolling=$rolling"
  grep -q "grain_wall: .*rolling" "$out/$method.yaml" || { echo "the scene has no rolling key"; exit 1; }
  OPENBLAS_NUM_THREADS=1 "$gembem" run "$out/$method.yaml" -o "$out/$method" --quiet > /dev/null
  if /usr/bin/python3 "$check" "$out/$method"; then ok "$method: the final state is an equilibrium with rolling moments"
  else bad "$method: the final state is not an equilibrium"; fi
  if /usr/bin/python3 "$steperr" "$out/$method"; then ok "$method: steps.csv's error columns recomputed"
  else bad "$method: steps.csv's error columns differ from the state's"; fi
done
# The moments are there: nonzero on most contacts, some at the limit eta R* pn.
if /usr/bin/python3 - "$out/reference" <<'EOF'
import csv, sys
run = sys.argv[1]
g = list(csv.DictReader(open(f"{run}/state_grains.csv")))
rows = list(csv.DictReader(open(f"{run}/state_contacts.csv")))
nonzero = at_limit = 0
for c in rows:
    ri = float(g[int(c["i"])]["r"])
    rs = ri if not c["j"].isdigit() else ri * float(g[int(c["j"])]["r"]) / (ri + float(g[int(c["j"])]["r"]))
    mr, limit = abs(float(c["mr"])), 0.1 * rs * float(c["pn"])
    nonzero += mr > 0
    at_limit += mr >= limit * (1 - 1e-9)
print(f"  {len(rows)} contacts, {nonzero} with a rolling moment, {at_limit} at the limit")
sys.exit(0 if nonzero > len(rows) / 2 and at_limit > 0 else 1)
EOF
then ok "rolling moments on most contacts, some at their limit"; else bad "too few rolling moments"; fi
# Rolling changes the answer: the stresses of the same path without it differ.
scene_edit "$out/reference.yaml" -o "$out/none.yaml" --delete materials.grain_grain.rolling \
  --delete materials.grain_wall.rolling
OPENBLAS_NUM_THREADS=1 "$gembem" run "$out/none.yaml" -o "$out/none" --quiet > /dev/null
last_s() { csv_awk '{ s = $col("s1") " " $col("s2") } END { print s }' "$1/steps.csv"; }
s_with=$(last_s "$out/reference"); s_none=$(last_s "$out/none")
if [ "$s_with" != "$s_none" ] && ! head -1 "$out/none/state_contacts.csv" | grep -q mr; then
  ok "without the rolling key: no mr column, another path (s1 s2: $s_none against $s_with)"
else bad "rolling did not change the run, or a scene without it writes mr"; fi
# Negative controls: the checker must refuse these.
cp -r "$out/global" "$out/moment"
# the grain-grain contact with the largest pn (its limit is far): mr + 500 dyn cm, 1e3 dyn of moment / r
csv_awk 'NR == FNR { if (FNR > 1 && $col("j") ~ /^[0-9]+$/ && $col("pn") > best) { best = $col("pn"); row = FNR }; next }
  FNR == row { $col("mr") = sprintf("%.17g", $col("mr") + 500) } 1' OFS=, \
  "$out/global/state_contacts.csv" "$out/global/state_contacts.csv" > "$out/moment/state_contacts.csv"
if /usr/bin/python3 "$check" "$out/moment" > "$out/moment.log" || ! grep -q "fixing force" "$out/moment.log" ||
   grep -q "rolling moment exceeds" "$out/moment.log"; then
  bad "a rolling moment changed by 500 dyn cm passed"
else ok "a rolling moment changed by 500 dyn cm fails the moment balance: $(grep FAIL "$out/moment.log")"; fi
cp -r "$out/global" "$out/limit"
csv_awk 'NR > 1 && $col("j") ~ /^[0-9]+$/ && !done { $col("mr") = sprintf("%.17g", 0.05 * $col("pn")); done = 1 } 1' OFS=, \
  "$out/global/state_contacts.csv" > "$out/limit/state_contacts.csv"
if /usr/bin/python3 "$check" "$out/limit" > "$out/limit.log" || ! grep -q "rolling moment exceeds" "$out/limit.log"; then
  bad "a rolling moment of 0.05 pn (the limit is at most 0.1 x 0.225 pn) passed"
else ok "a rolling moment past its limit fails"; fi
# Read back exactly: relax from the state; it is an equilibrium, so nothing moves and mr is unchanged.
scene_edit "$out/reference.yaml" -o "$out/restart.yaml" --delete grains --delete box \
  --add initial_state=reference/state.yaml --set 'loading=[{relax: {steps: 1}}]'
OPENBLAS_NUM_THREADS=1 "$gembem" run "$out/restart.yaml" -o "$out/restart" --quiet > /dev/null 2> "$out/restart.log"
cols() { csv_awk '{ print $col("i"), $col("j"), $col("pn"), $col("pt"), $col("mr") }' "$1"; }
if [ "$(cols "$out/reference/state_contacts.csv")" = "$(cols "$out/restart/state_contacts.csv")" ] &&
   grep -q mr "$out/restart/state_contacts.csv"; then
  ok "a restart from the state reads every rolling moment back exactly"
else bad "the restarted state's contacts differ"; fi
# And through a checkpoint (format 3 carries mr): killed at its 25th output write (GB_TEST_KILL_AT,
# tests/cli/run_resume.sh), resumed to the end, the same final contacts byte for byte.
scene_edit "$out/reference.yaml" -o "$out/ck.yaml" --add 'output={checkpoint_every: 1}'
OPENBLAS_NUM_THREADS=1 "$gembem" run "$out/ck.yaml" -o "$out/ck_full" --quiet > /dev/null 2>&1
(GB_TEST_KILL_AT=25 OPENBLAS_NUM_THREADS=1 "$gembem" run "$out/ck.yaml" -o "$out/ck_kill" --quiet > /dev/null 2>&1) 2> /dev/null || true
for k in 1 2 3 4 5; do
  grep -q '^4,' "$out/ck_kill/steps.csv" 2> /dev/null && [ -f "$out/ck_kill/state.yaml" ] && break
  OPENBLAS_NUM_THREADS=1 "$gembem" run --resume "$out/ck_kill" --quiet > /dev/null 2>&1 || true
done
if grep -q 'interrupted: 1' "$out/ck_kill/run_info.yaml" && cmp -s "$out/ck_full/state_contacts.csv" "$out/ck_kill/state_contacts.csv"; then
  ok "killed and resumed from a checkpoint: the same rolling moments, byte for byte"
else bad "a run resumed from a checkpoint ends with other contacts (or was not interrupted)"; fi
[ $fails = 0 ] || { echo "$fails failure(s)"; exit 1; }
