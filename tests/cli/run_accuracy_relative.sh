#!/usr/bin/env bash
# solver.accuracy {relative: r} against the absolute accuracy it resolves to: a
# one-step run with {relative: 1e-4}, then the same scene with the accuracy that steps.csv says the
# step was solved to (%.17g: exact); the two run directories must be equal byte for byte (steps.csv's
# seconds and run_info.yaml aside). The step's force scale is checked too: the stage's load force
# (stress x mean diameter) for the first step of the three discs, whose contacts touch within
# rounding; the mean normal force of the start's contacts, recomputed here from the state file the
# step starts from, for a shear step from a prepared state and for a host's relaxation.
#   run_accuracy_relative.sh GEMBEM
set -u
gembem=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
source "$root/tests/csv.sh"
source "$root/tests/scene.sh"
source "$root/tools/lib.sh"
gb_test_begin
cell() { # cell FILE NAME ROW: the value of column NAME in data row ROW (0 = step 0)
  csv_awk -v name="$2" -v row="$3" 'NR == row + 2 { print $col(name) }' "$1"
}
# same NAME SCENE_WITH_RELATIVE: runs it, then with the resolved absolute accuracy, and compares
same() {
  local name=$1 scene=$2
  "$gembem" run "$scene" -o "$out/$name.rel" --quiet || { bad "$name: the relative run failed"; return; }
  local a; a=$(cell "$out/$name.rel/steps.csv" accuracy 1)
  scene_edit "$scene" -o "${scene%.yaml}.abs.yaml" --set solver.accuracy="$a"
  "$gembem" run "${scene%.yaml}.abs.yaml" -o "$out/$name.abs" --quiet || { bad "$name: the absolute run failed"; return; }
  if diff -r -x run_info.yaml -x steps.csv -x scene.yaml -x .lock -I "^# A scene starts from it" "$out/$name.rel" "$out/$name.abs" > "$out/diff" &&
     cmp -s <(csv_awk '{ $col("seconds") = "" } 1' OFS=, "$out/$name.rel/steps.csv") \
            <(csv_awk '{ $col("seconds") = "" } 1' OFS=, "$out/$name.abs/steps.csv"); then
    ok "$name: {relative: 1e-4} resolved to a = $a; the absolute run with it is the same, bit for bit"
  else
    bad "$name: the relative and the absolute run differ"; head -5 "$out/diff"
  fi
}
# scale NAME EXPECTED: step 1's force_scale against a value computed here, to 1e-12
scale() {
  local got; got=$(cell "$out/$1.rel/steps.csv" force_scale 1)
  /usr/bin/python3 -c "import sys; g, e = float('$got'), float('$2'); sys.exit(abs(g - e) > 1e-12 * e)" &&
    ok "$1: force scale $got = $2" || bad "$1: force scale $got, expected $2"
}

# case1's loading: 0 isotropic (10 steps), 1 shear_mean_stress (100 steps)
case1=$root/validation/three_discs/case1.yaml; relative=(--set 'solver.accuracy={relative: 1e-4}')
# 1. The three discs' first step: isotropic 1.5e5 dyn/cm on discs of diameter 2 cm: 3e5 dyn.
scene_edit "$case1" -o "$out/iso.yaml" "${relative[@]}" --set loading.0.isotropic.steps=1 --delete loading.1 \
  --delete output
same iso "$out/iso.yaml"
scale iso 3e5
# 2. A shear step from the prepared three discs: the scale is their mean normal force.
"$gembem" run "$out/iso.abs.yaml" -o "$out/prep" --quiet || bad "the preparation failed"
scene_edit "$case1" -o "$out/shear.yaml" "${relative[@]}" --set loading.1.shear_mean_stress.steps=1 --delete loading.0 \
  --delete grains --delete box --delete output --add initial_state="$out/prep/state.yaml"
same shear "$out/shear.yaml"
mean_pn() { /usr/bin/python3 -c "
import csv; p = [float(r['pn']) for r in csv.DictReader(open('$1')) if float(r['overlap']) > 0]
print(repr(sum(p) / len(p)))"; }
scale shear "$(mean_pn "$out/prep/state_contacts.csv")"
# 3. A host's 27 grains relaxed from their overlapping placement (global solver, the coupling): the
# scale is the mean normal force of the placement's contacts, grains' and boundary particles'.
#    (load_grains.yaml's loading: 0 relax, 1 and 2 host_load)
scene_edit "$root/tests/hybrid/load_grains.yaml" -o "$out/host.yaml" "${relative[@]}" --delete loading.2 \
  --delete loading.1 --add 'output={contacts_every: 1}'
same host "$out/host.yaml"
scale host "$(mean_pn "$out/host.rel/contacts/contacts_000000.csv")"
gb_test_end
