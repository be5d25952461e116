#!/usr/bin/env bash
# Issue 22's trap and every warning of a result that is noise (docs/run-directory.md, "Warnings where
# the result is noise"), on stderr and in run_info.yaml's warnings:
#  - the 300 jammed discs of the fixture (tools/jammed_packing.sh) under strain steps with
#    {relative: 1e-4}: no warning, and the verdict's largest relative residual within 1e-4;
#  - the same grains spread apart by 4 % (a loose packing, kept as a file) compressed with an absolute accuracy of
#    5e4 dyn, the mean contact force's order: the accuracy is not small against the contact forces,
#    the packing is not jammed (fewer than 3 contacts per load-carrying grain), the contact count
#    swings (a tenfold stress in one step), the localisation index is undefined (a step where the
#    walls barely moved);
#  - a host with two grains relaxed, nothing loading it: max_concentration is undefined.
#   run_accuracy_warnings.sh GEMBEM JAMMED_DIR
set -u
gembem=$1 jammed=$(cd "$2" && pwd)
root=$(cd "$(dirname "$0")/../.." && pwd)
source "$root/tools/lib.sh"
gb_test_begin
box=$(sed -n 's/^box: //p' "$jammed/scene.yaml")
scene() { # scene GRAINS ACCURACY BOX STAGE...
  local grains=$1 accuracy=$2 box=$3; shift 3
  table3_scene_head "$grains"
  printf 'box: %s\nsolver: {method: global, accuracy: %s}\nloading:\n' "$box" "$accuracy"
  for stage in "$@"; do printf '  - %s\n' "$stage"; done
  printf 'output: {measures_every: 0}\n'
}
# expect NAME TEXT...: each text on stderr and among run_info.yaml's warnings
expect() {
  local name=$1; shift
  for want in "$@"; do
    grep -q "warning: .*$want" "$out/$name.err" || bad "$name: no '$want' on stderr"
    grep -q "^  - \".*$want" "$out/$name/run_info.yaml" || bad "$name: no '$want' in run_info.yaml's warnings"
  done
}

# The jammed packing, relative accuracy: silent.
scene "$jammed/jammed.csv" "{relative: 1e-4}" "$box" "strain: {de1: 0.0005, de2: 0, steps: 4}" > "$out/jammed.yaml"
"$gembem" run "$out/jammed.yaml" -o "$out/jammed" --quiet 2> "$out/jammed.err" || bad "jammed: the run failed"
if [ -s "$out/jammed.err" ]; then bad "jammed: warned: $(cat "$out/jammed.err")"
else ok "jammed, {relative: 1e-4}: no warning"; fi
grep -q '^warnings: \[\]' "$out/jammed/run_info.yaml" || bad "jammed: run_info.yaml's warnings are not empty"
res=$(sed -n 's/^  largest_relative_residual: \([^ ]*\).*/\1/p' "$out/jammed/run_info.yaml")
/usr/bin/python3 -c "import sys; sys.exit(not 0 < float('$res') <= 1e-4)" &&
  ok "jammed: the verdict's largest relative residual $res <= 1e-4" || bad "jammed: largest relative residual '$res'"

# The same grains 4 % apart, a loose accuracy: the trap. The loose grains are a file
# (tests/cli/warn/loose_300.csv: the fixture's discs as an earlier tools/jammed_packing.sh
# made them, spread by 4 % about the box centre): whether a loose run jams within a step is chaotic,
# so that a packing made by other FIRE arithmetic gave other warnings.
scene "$root/tests/cli/warn/loose_300.csv" "5.0e4" "{left: 0.26, right: 14.09, bottom: 0.26, top: 14.09}" \
  "isotropic: {stress: 1.5e4, steps: 3}" "isotropic: {stress: 1.5e5, steps: 1}" > "$out/loose.yaml"
"$gembem" run "$out/loose.yaml" -o "$out/loose" --quiet 2> "$out/loose.err" || bad "loose: the run failed"
expect loose "the accuracy is not small against the contact forces" "the packing is not jammed" \
  "the contact count swings from step to step" "localisation_index is undefined"
[ $fail = 0 ] && ok "loose, accuracy 5e4 dyn: $(grep -c warning "$out/loose.err") warnings on stderr and in run_info.yaml"

# A host that nothing loads: its concentration is a ratio of zeros.
"$gembem" run "$root/tests/cli/good_host.yaml" -o "$out/host" --quiet 2> "$out/host.err" || bad "host: the run failed"
expect host "max_concentration is undefined"
grep -q "^1,.*,none,nan$" "$out/host/localisation.csv" && ok "host: max_concentration nan at step 1" ||
  bad "host: localisation.csv's step 1 is not undefined"
gb_test_end
