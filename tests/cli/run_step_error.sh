#!/usr/bin/env bash
# steps.csv's error columns recomputed from the saved state by
# tools/check_step_error.py (its own sums of the stored contact forces: force scale, relative
# residual, walls' residual, Coulomb excess, mean normal force, coordination, rattlers; with a host
# the grains-host balance against host_particles.csv's K u + f0), and the final state checked by
# tools/check_equilibrium.py (its own contact detection) with the accuracy the last step resolved:
# the three discs of Kishino's case 1 with a relative accuracy (stress control, sliding contacts),
# and the 27-grain cavity packing of tests/hybrid/load_grains.yaml (global solver, host loads):
# tests/cli/scenes/step_error_discs.yaml and step_error_host.yaml.
#   run_step_error.sh GEMBEM
set -u
gembem=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail=0
for name in discs host; do
  "$gembem" run "$root/tests/cli/scenes/step_error_$name.yaml" -o "$out/$name" --quiet || { echo "FAIL $name did not run"; fail=1; continue; }
  /usr/bin/python3 "$root/tools/check_step_error.py" "$out/$name" || { echo "FAIL $name: steps.csv's errors"; fail=1; }
done
/usr/bin/python3 "$root/tools/check_equilibrium.py" "$out/discs" || { echo "FAIL discs: not an equilibrium"; fail=1; }
exit $fail
