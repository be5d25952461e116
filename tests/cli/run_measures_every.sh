#!/usr/bin/env bash
# output.measures_every (docs/measures.md): the files of fields/ only at the steps that
# are multiples of k (step 0 included), localisation.csv a row at every step whatever k, and its
# rows the same as with the fields at every step (byte for byte: the row does not depend on k).
# 1. The three discs (110 steps), k = 3: fields at 0, 3, ..., 108 only; 111 rows. With
#    output.localisation: false no localisation.csv, the other files the same.
# 2. The hybrid host_loading scene (3 steps, a host): k = 2 and k = 0 against the default (1):
#    host_wall/host_ring only at 0 and 2, no fields/ at all with 0, the same rows (the host's
#    columns then come from the wall-only measure).
# 3. The default by size: 5000 grains get no fields/ (run_info.yaml says why), 2 grains every step.
set -u
gembem=$1; root=$(cd "$(dirname "$0")/../.." && pwd)
source "$root/tests/csv.sh"
source "$root/tests/scene.sh"
source "$root/tools/lib.sh"
gb_test_begin

# The steps (sorted, one per line) of the files fields/<what>_NNNNNN.<ext> of a run directory.
steps_of() { ls "$1/fields" 2>/dev/null | sed -n "s/^$2_0*\([0-9][0-9]*\)\.$3\$/\1/p" | sort -n; }
expect_steps() { # dir what ext "expected steps"
  local got; got=$(steps_of "$1" "$2" "$3" | tr '\n' ' ' | sed 's/ $//')
  if [ "$got" = "$4" ]; then ok "$(basename "$1"): fields/$2 at steps [$got]"
  else bad "$(basename "$1"): fields/$2 at steps [$got], expected [$4]"; fi
}
expect_rows() { # dir count: localisation.csv has rows for steps 0 .. count-1, in order
  local got; got=$(csv_awk 'NR > 1 { print $col("step") }' "$1/localisation.csv" | tr '\n' ' ' | sed 's/ $//')
  local want; want=$(seq 0 $(($2 - 1)) | tr '\n' ' ' | sed 's/ $//')
  if [ "$got" = "$want" ]; then ok "$(basename "$1"): localisation.csv has a row for every step 0..$(($2 - 1))"
  else bad "$(basename "$1"): localisation.csv steps [$got], expected [$want]"; fi
}
same_rows() { # dir_a dir_b
  if cmp -s "$1/localisation.csv" "$2/localisation.csv"; then ok "$(basename "$2"): localisation.csv identical to $(basename "$1")'s"
  else bad "$(basename "$2"): localisation.csv differs from $(basename "$1")'s"; diff "$1/localisation.csv" "$2/localisation.csv" | head -4; fi
}

# 1. Three discs, 110 steps.
"$gembem" run "$root/tests/cli/scenes/every3.yaml" -o "$out/discs3" --quiet || bad "three discs, k = 3: did not run"
"$gembem" run "$root/tests/cli/scenes/every1.yaml" -o "$out/discs1" --quiet || bad "three discs, default: did not run"
want=$(seq 0 3 110 | tr '\n' ' ' | sed 's/ $//')
for w in grains:csv sliding:csv triangles:vtu; do expect_steps "$out/discs3" "${w%:*}" "${w#*:}" "$want"; done
expect_steps "$out/discs1" grains csv "$(seq 0 110 | tr '\n' ' ' | sed 's/ $//')"
n=$(grep -c '<DataSet ' "$out/discs3/fields/triangles.pvd")
[ "$n" -eq 37 ] && ok "discs3: triangles.pvd lists the 37 written steps" || bad "discs3: triangles.pvd lists $n steps, expected 37"
expect_rows "$out/discs3" 111
same_rows "$out/discs1" "$out/discs3"
grep -q '^measures_every: 3 ' "$out/discs3/run_info.yaml" && ok "discs3: run_info.yaml records measures_every: 3" \
  || bad "discs3: run_info.yaml does not record measures_every"

# 1b. output.localisation: false: no localisation.csv, the rest as with it (fields/ at the same
#     steps and the same bytes, micromechanics.csv), run_info.yaml says so.
scene_edit "$root/tests/cli/scenes/every3.yaml" -o "$out/noloc.yaml" --add output.localisation=false
"$gembem" run "$out/noloc.yaml" -o "$out/noloc" --quiet || bad "three discs, no localisation: did not run"
[ ! -e "$out/noloc/localisation.csv" ] && ok "noloc: no localisation.csv" || bad "noloc: localisation.csv written"
for w in grains:csv sliding:csv triangles:vtu; do expect_steps "$out/noloc" "${w%:*}" "${w#*:}" "$want"; done
if cmp -s "$out/discs3/micromechanics.csv" "$out/noloc/micromechanics.csv" &&
   diff -rq "$out/discs3/fields" "$out/noloc/fields" > /dev/null; then ok "noloc: micromechanics.csv and fields/ as with localisation.csv"
else bad "noloc: micromechanics.csv or fields/ differ from discs3's"; fi
grep -q '^    localisation: false$' "$out/noloc/run_info.yaml" && ok "noloc: run_info.yaml records localisation: false" \
  || bad "noloc: run_info.yaml: $(grep -n localisation "$out/noloc/run_info.yaml")"

# 2. A host: the wall-only host measure of the rows equals the full one.
host=$root/tests/hybrid/host_loading.yaml
for k in 2 0; do
  scene_edit "$host" -o "$out/host$k.yaml" --add output.measures_every=$k
  "$gembem" run "$out/host$k.yaml" -o "$out/host$k" --quiet || bad "host, k = $k: did not run"
done
"$gembem" run "$host" -o "$out/host1" --quiet || bad "host, default: did not run"
for w in host_wall host_ring grains sliding; do expect_steps "$out/host2" $w csv "0 2"; expect_steps "$out/host1" $w csv "0 1 2 3"; done
[ ! -e "$out/host0/fields" ] && ok "host0: no fields/ with measures_every: 0" || bad "host0: fields/ was created"
for k in 0 2; do expect_rows "$out/host$k" 4; same_rows "$out/host1" "$out/host$k"; done
head -1 "$out/host0/localisation.csv" | grep -q ',s_ref,s_ref_kind,max_concentration$' && ok "host0: the host's columns" \
  || bad "host0: localisation.csv lacks the host's columns"

# 3. Default by size: 5000 grains on a grid, touching nothing (converged at once), and 2 grains.
awk 'BEGIN { print "x,y,r"; for (i = 0; i < 100; i++) for (j = 0; j < 50; j++) printf "%d.5,%d.5,0.4\n", i, j }' > "$out/grid.csv"
cat > "$out/big.yaml" <<EOF
$(table3_scene_head grid.csv)
box: {left: 0, right: 100, bottom: 0, top: 50}
solver: {accuracy: 100}
loading:
  - relax: {steps: 2}
EOF
"$gembem" run "$out/big.yaml" -o "$out/big" --quiet || bad "5000 grains: did not run"
[ ! -e "$out/big/fields" ] && ok "big: 5000 grains, no measures_every: no fields/" || bad "big: fields/ written by default"
expect_rows "$out/big" 3
grep -q '^measures_every: 0 .*the default from 5000 grains up' "$out/big/run_info.yaml" \
  && ok "big: run_info.yaml says the default turned the fields off" || bad "big: run_info.yaml: $(grep measures "$out/big/run_info.yaml")"
"$gembem" run "$root/tests/cli/good.yaml" -o "$out/small" --quiet || bad "good.yaml: did not run"
grep -q '^measures_every: 1 .*the default below 5000 grains' "$out/small/run_info.yaml" \
  && ok "small: the default is every step" || bad "small: run_info.yaml: $(grep measures "$out/small/run_info.yaml")"

gb_test_end
