#!/usr/bin/env bash
# gembem pack, checked by check_pack.py without gembem's code (its docstring says what), and:
# a seeded packing made twice gives the same bytes; the solid fraction target is reached to 1e-9
# (the radii are scaled to it); the stress target is within 1 % of Love's stress from the written
# contacts, and within 2 % (1 % with friction finished by the global solver, whose walls follow the
# target) of the walls' stresses that gembem run measures from the state; a
# run scene starts from the cavity packing's state; a packing with friction (pack.friction_deg),
# and one with rolling resistance too, is in balance, inside its cone and looser; 4 500 discs
# grown on 1 and on 2 threads (solver.threads) give the same bytes, frictionless and with friction.
#   run_pack.sh GEMBEM GMSH PYTHON
set -u
gembem=$1; gmsh=$2; python=$3; dir=$(cd "$(dirname "$0")" && pwd); root=$dir/../..
out=$(mktemp -d); fail=0
trap 'rm -rf "$out"' EXIT
source "$dir/../scene.sh"
check() { "$python" "$dir/check_pack.py" "$@" || fail=$((fail + 1)); }
run() { "$gembem" "$@" --quiet || { echo "FAIL gembem $*"; fail=$((fail + 1)); }; }
cp "$dir"/*.yaml "$out/"
"$gmsh" -1 -format msh2 -clscale 0.5 "$root/meshes/irregular_cavity.geo" -o "$out/irregular.msh" > "$out/gmsh.log" 2>&1 ||
  { echo "FAIL gmsh could not mesh irregular_cavity.geo"; exit 1; }
cd "$out"

run pack cavity_deposition.yaml -o deposition
check deposition --msh irregular.msh --max-overlap 0.02 --accuracy 0.001 --weight 0.1
run pack cavity_deposition.yaml -o deposition2
for f in state_grains.csv state_contacts.csv state_host.csv; do
  cmp -s deposition/$f deposition2/$f || { echo "FAIL $f differs between two runs of one seed"; fail=$((fail + 1)); }
done
strip() { grep -v -e '^made:' -e '^seconds:' -e '^command:' "$1"; }
[ "$(strip deposition/pack_info.yaml)" = "$(strip deposition2/pack_info.yaml)" ] ||
  { echo "FAIL pack_info.yaml differs between two runs of one seed"; fail=$((fail + 1)); }
scene_edit cavity_deposition.yaml -o cavity_deposition.yaml --set pack.seed=4   # of 3
run pack cavity_deposition.yaml -o deposition3
cmp -s deposition/state_grains.csv deposition3/state_grains.csv && { echo "FAIL another seed, the same grains"; fail=$((fail + 1)); }
run run cavity_run.yaml -o cavity_run

run pack cavity_growth.yaml -o growth
check growth --msh irregular.msh --max-overlap 0.05 --accuracy 0.001 --solid-fraction 0.73
run pack box_growth.yaml -o box
check box --box 0 10 0 10 --max-overlap 0.02 --accuracy 100 --solid-fraction 0.82
run pack box_stress.yaml -o stress
check stress --box 0 10 0 10 --max-overlap 0.05 --accuracy 100 --stress 1e5
# the walls' mean stress that gembem run measures from packing DIR's state, against the target 1e5
# to TOLERANCE (relative)
walls_stress() {
  scene_edit box_stress_run.yaml -o $1_run.yaml --set initial_state=$1/state.yaml
  run run $1_run.yaml -o $1_run
  "$python" - "$1" "$2" <<'PY' || fail=$((fail + 1))
import csv, sys
row = next(csv.DictReader(open(f"{sys.argv[1]}_run/steps.csv")))
p = 0.5 * (float(row["s1"]) + float(row["s2"]))
print(f"{sys.argv[1]}: the walls' mean stress {p:.6g}, target 1e5 +- {100 * float(sys.argv[2]):g} %")
sys.exit(0 if abs(p / 1e5 - 1) <= float(sys.argv[2]) else 1)
PY
}
walls_stress stress 0.02
# pack.friction_deg: the grains packed with friction are in balance with their tangential forces
# (moments too, check_pack.py), inside the cone of the packing's angle, and looser than the same
# seed packed frictionless (frictional discs jam at a lower solid fraction: docs/packing.md)
scene_edit box_stress.yaml -o friction.yaml --add pack.friction_deg=20   # of 25
run pack friction.yaml -o friction
check friction --box 0 10 0 10 --max-overlap 0.05 --accuracy 100 --friction-deg 20
"$python" - <<'PY' || fail=$((fail + 1))
import sys
phi = {d: float(next(l for l in open(d + "/pack_info.yaml") if l.startswith("solid_fraction:")).split()[1])
       for d in ("stress", "friction")}
print(f"friction: solid fraction {phi['friction']:.4f} packed at 20 degrees, {phi['stress']:.4f} frictionless")
sys.exit(0 if phi["friction"] < phi["stress"] - 0.01 else 1)
PY
# with the global solver, FIRE stops at 8 times the accuracy and the solver takes the last factor with
# the scene's friction and the walls at the target stress, the state then mapped back onto the box
# (src/pack/pack.c's SETTLE_HELD, gb_sim_fit_box): the written state in balance all the same, each
# tangential force within the scene's cone (25 degrees), where the solver leaves them, its solid
# fraction as reported, and both Love's and the walls' stress at the target
scene_edit friction.yaml -o friction_global.yaml --add solver.method=global
run pack friction_global.yaml -o friction_global
check friction_global --box 0 10 0 10 --max-overlap 0.05 --accuracy 100 --friction-deg 25 --stress 1e5
walls_stress friction_global 0.01
# with rolling resistance too (its moments in the balance, each within eta R* pn)
scene_edit friction.yaml -o rolling.yaml --add materials.grain_grain.rolling='{kr: 1.0e6, eta: 0.2}'
run pack rolling.yaml -o rolling
check rolling --box 0 10 0 10 --max-overlap 0.05 --accuracy 100 --friction-deg 20 --eta 0.2
# solver.threads: 4 500 discs (above FIRE's threshold for its threads) grown with 1 and 2 threads
# give the same bytes (src/pack/fire.c's fixed decomposition); FIRE calls no BLAS, so only its own loops'
# thread count differs between the two runs
for t in 1 2; do
  scene_edit box_growth.yaml -o threads$t.yaml --set pack.count=4500 --set box.right=38 --set box.top=38 \
    --add solver.threads=$t   # of 300 grains in 10 x 10
  run pack threads$t.yaml -o threads$t
  scene_edit threads$t.yaml -o friction_threads$t.yaml --add pack.friction_deg=10   # the frictional loop
  run pack friction_threads$t.yaml -o friction_threads$t
done
for f in state_grains.csv state_contacts.csv; do
  for d in threads friction_threads; do
    cmp -s ${d}1/$f ${d}2/$f && echo "ok   $d $f: the same bytes on 1 and 2 threads" ||
      { echo "FAIL $d $f differs between 1 and 2 threads"; fail=$((fail + 1)); }
  done
done
echo "$fail failures"
[ $fail -eq 0 ]
