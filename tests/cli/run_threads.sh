#!/usr/bin/env bash
# solver.threads (the contacts' update and sums on OpenMP threads, src/gem/relax.c, and the
# smoother's sums over the grains, src/solver/inertial.c): the same run with 1 and with 2 threads
# gives the same bits, since every sum is taken in an order that the pair list and the grains fix
# (tests/cli/scenes/threads.yaml: 800 discs, more than the thresholds of the parallel update, of
# the contacts' chunks and of the smoother's blocks; a friction relaxation and 3 strain steps of
# the line search). Also refused: threads 0.
# Bits are compared on purpose: both runs make the same BLAS and UMFPACK calls with the same
# OPENBLAS_NUM_THREADS (inherited); only gembem's own loops change their thread count, and their
# sums are taken in a fixed order (the property under test, not an accident of one machine).
set -u
gembem=$1 packgen=$2; root=$(cd "$(dirname "$0")/../.." && pwd)
source "$root/tests/csv.sh"
source "$root/tests/scene.sh"
out=$(mktemp -d); fail=0
trap 'rm -rf "$out"' EXIT
"$packgen" --method push --n 800 --diameters 0.6,0.9,1.2 --porosity 0.18 --max-overlap 0.015 --seed 3 \
  --out "$out/threads_grains.csv" > /dev/null || { echo "FAIL gb_packgen"; exit 1; }
box=$(grep '^box:' "$out/threads_grains.box.yaml" | sed 's/^box: //')
# tests/cli/scenes/threads.yaml with the packing's grains file and box, and THREADS threads
threads_scene() { # OUT.yaml THREADS
  scene_edit "$root/tests/cli/scenes/threads.yaml" -o "$1" --set grains.file="$out/threads_grains.csv" --set "box=$box" \
    --set solver.threads="$2"
}
for t in 1 2; do
  threads_scene "$out/t$t.yaml" $t
  OMP_NUM_THREADS=2 "$gembem" run "$out/t$t.yaml" -o "$out/t$t" --quiet || { echo "FAIL the run with $t threads"; fail=1; }
done
# every column of steps.csv but the wall-clock seconds, and the final state
for t in 1 2; do csv_awk -v OFS=, '{ $col("seconds") = 0; print }' "$out/t$t/steps.csv" > "$out/steps$t.csv"; done
for f in steps1.csv:steps2.csv t1/state_grains.csv:t2/state_grains.csv t1/state_contacts.csv:t2/state_contacts.csv; do
  if cmp -s "$out/${f%%:*}" "$out/${f##*:}"; then echo "ok   ${f##*:} the same bits with 1 and 2 threads"
  else echo "FAIL ${f##*:} differs between 1 and 2 threads"; fail=1; fi
done
steps=$(csv_awk 'NR > 1 { n++ } END { print n }' "$out/t2/steps.csv")
[ "$steps" = 5 ] && echo "ok   5 rows (the initial state, the relaxation, 3 steps)" || { echo "FAIL $steps rows"; fail=1; }
threads_scene "$out/t0.yaml" 0
msg=$("$gembem" run "$out/t0.yaml" -o "$out/t0" --quiet 2>&1); rc=$?
if [ $rc = 2 ] && [ ! -e "$out/t0" ] && grep -q 'threads' <<< "$msg"; then echo "ok   threads: 0 refused ($msg)"
else echo "FAIL threads: 0: exit $rc, $msg"; fail=1; fi
exit $fail
