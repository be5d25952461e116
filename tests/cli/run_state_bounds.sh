#!/usr/bin/env bash
# What gembem admits, it can run, write and read back: a state at the admission bounds of
# src/scene/admit.h (forces and kn times a radius at most 1e145) either runs or fails with a
# message of its own, and its checkpoint resumes; just past the bounds it is refused at its file,
# line and column. No admitted input was found whose run goes non-finite: the bound keeps every
# force's square finite. The scenes are tests/cli/bad/contacts_overflow.yaml (a tangential force
# in contacts_overflow.csv: line 2, column 5, after "0,1,") and stiffness_overflow.yaml (kn of
# grain_wall: line 7, column 20) with other values.
#   run_state_bounds.sh GEMBEM
set -u
gembem=$1
bad=$(cd "$(dirname "$0")" && pwd)/bad
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail=0
sed 's/isotropic: {stress: 1.5e5, steps: 2}/relax: {steps: 1}/' "$bad/contacts_overflow.yaml" > "$out/pt.yaml"
cp "$bad/contacts_overflow.yaml" "$out/iso.yaml"
sed 's/1\.0e300/1.0e145/' "$bad/stiffness_overflow.yaml" > "$out/kn.yaml"
sed 's/1\.0e300/1.000001e145/' "$bad/stiffness_overflow.yaml" > "$out/kn_over.yaml"
cd "$out"

# just past the bounds: refused where the value stands
printf 'i,j,pt\n0,1,1.000001e145\n' > contacts_overflow.csv
msg=$("$gembem" run pt.yaml -o r_pt_over --quiet 2>&1); code=$?
[ $code = 2 ] && [[ $msg == *"contacts_overflow.csv:2:5: pt: expected a magnitude of at most 1e145"* ]] &&
  [ ! -e r_pt_over ] || { echo "FAIL pt 1.000001e145: exit $code, '$msg'"; fail=1; }
msg=$("$gembem" run kn_over.yaml -o r_kn_over --quiet 2>&1); code=$?
[ $code = 2 ] && [[ $msg == *"kn_over.yaml:7:20: materials.grain_wall.kn"* ]] && [ ! -e r_kn_over ] ||
  { echo "FAIL kn 1.000001e145: exit $code, '$msg'"; fail=1; }

# a tangential force of 1e145: the run completes, and its final state starts a run
printf 'i,j,pt\n0,1,-1e145\n' > contacts_overflow.csv
"$gembem" run pt.yaml -o r_pt --quiet 2>/dev/null || { echo "FAIL pt -1e145: the run failed"; fail=1; }
grep -qiE 'nan|inf' r_pt/state_contacts.csv r_pt/state_grains.csv && { echo "FAIL pt: a non-finite value in the state"; fail=1; }
sed "/^grains:/,/contacts:/d; s|^box:.*|initial_state: r_pt/state.yaml|" pt.yaml > again.yaml
"$gembem" run again.yaml -o r_again --quiet 2>/dev/null || { echo "FAIL pt: a run from the state it wrote failed"; fail=1; }

# isotropic compression squeezes the two discs between the walls (the box ends lower than a
# diameter): the state it wrote is admitted, as each disc crosses the walls within
# grains.max_overlap, and starts a run
printf 'i,j,pt\n0,1,0\n' > contacts_overflow.csv
"$gembem" run iso.yaml -o r_iso --quiet 2>/dev/null || { echo "FAIL iso: the compression failed"; fail=1; }
height=$(awk '/^box:/ { for (k = 1; k <= NF; k++) if ($k == "top:") top = $(k + 1); for (k = 1; k <= NF; k++) if ($k == "bottom:") bottom = $(k + 1) }
  END { gsub(/[,}]/, "", top); gsub(/[,}]/, "", bottom); print top - bottom }' r_iso/state.yaml)
awk -v h="$height" 'BEGIN { exit !(h < 2) }' || echo "note: the compressed box is $height high, not below a diameter"
sed "/^grains:/,/contacts:/d; s|^box:.*|initial_state: r_iso/state.yaml|" iso.yaml > iso_again.yaml
msg=$("$gembem" run iso_again.yaml -o r_iso_again --quiet 2>&1) || { echo "FAIL iso: a run from the state it wrote: '$msg'"; fail=1; }

# kn = 1e145 with a relative accuracy: the step fails on round-off (exit 3, saying so), and the
# checkpoint it leaves resumes to the same failure, never a parse error
msg=$("$gembem" run kn.yaml -o r_kn --quiet 2>&1); code=$?
[ $code = 3 ] && [[ $msg == *"at the round-off of these springs"* ]] ||
  { echo "FAIL kn 1e145: exit $code, '$msg'"; fail=1; }
grep -q '^status: not converged' r_kn/run_info.yaml || { echo "FAIL kn: run_info.yaml's status"; fail=1; }
[ -s r_kn/checkpoint.txt ] && ! grep -qiE 'nan|inf' r_kn/checkpoint.txt || { echo "FAIL kn: no whole checkpoint"; fail=1; }
msg2=$("$gembem" run --resume r_kn --quiet 2>&1); code=$?
[ $code = 3 ] && [ "$msg2" = "$msg" ] || { echo "FAIL kn: --resume gave exit $code, '$msg2'"; fail=1; }
[ $fail = 0 ] && echo "ok: refused past the bounds at file:line:column; at them a completed run and a failed one that resumes"
exit $fail
