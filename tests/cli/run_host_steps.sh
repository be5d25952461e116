#!/usr/bin/env bash
# host_steps.csv of loaded hosts, through the command line: one row per step and group, with the
# values the loading program prescribes (computed here from the scene: biaxial, 2 + 2 steps; the
# sides' pressure 5 + 2 x 10 on a side 10 cm long carries 250 kgf; the top ends at uy = -0.002)
# and, for the infinite plane, the remote stress columns (-5 + 3 x -10, 3 x -20, 3 x 5).
set -u
gembem=$1; root=$(cd "$(dirname "$0")/../.." && pwd)
source "$root/tests/csv.sh"
out=$(mktemp -d); fail=0
check() { if ! csv_awk "$2" "$1"; then echo "FAIL $1: $3"; fail=$((fail + 1)); else echo "ok   $3"; fi; }
"$gembem" run "$root/tests/hybrid/load_biaxial.yaml" -o "$out/biaxial" --quiet || { echo "FAIL biaxial did not run"; exit 1; }
f=$out/biaxial/host_steps.csv
check "$f" 'NR == 1 && $0 != "step,group,condition,ux,uy,fx,fy" { exit 1 }' "biaxial header"
check "$f" 'END { exit !(NR == 1 + 5 * 5) }' "biaxial: 5 groups x 5 steps (0 to 4)"
check "$f" '$col("step") == 4 && $col("group") == "left" {
  ok = ($col("condition") == "pressure" && $col("fx") > 250 - 1e-9 && $col("fx") < 250 + 1e-9) } END { exit !ok }' \
  "biaxial: left carries 250 kgf at step 4"
check "$f" '$col("step") == 4 && $col("group") == "top" { ok = ($col("condition") == "displacement" && $col("uy") == -0.002) }
  END { exit !ok }' \
  "biaxial: top at uy = -0.002 at step 4"
"$gembem" run "$root/tests/hybrid/load_remote.yaml" -o "$out/remote" --quiet || { echo "FAIL remote did not run"; exit 1; }
f=$out/remote/host_steps.csv
check "$f" 'NR == 1 && $0 != "step,group,condition,ux,uy,fx,fy,sxx,syy,sxy" { exit 1 }' "remote header"
check "$f" '$col("step") == 3 { ok = ($col("group") == "cavity" && $col("sxx") == -35 && $col("syy") == -60 && $col("sxy") == 15) }
  END { exit !ok }' \
  "remote: stress (-35, -60, 15) at step 3"
rm -rf "$out"
[ $fail -eq 0 ]
