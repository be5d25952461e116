#!/usr/bin/env bash
# Every scene in tests/cli/bad is refused before any computation: exit status 2, a message with
# the expected file:line:column and text (the .expect file beside it), and no run directory.
# The scenes of tests/cli/bad_msh read the .msh that gmsh writes of the .geo beside them (its
# first line gives gmsh's arguments), made at test time: each line of their .expect must appear.
#   run_bad_scenes.sh GEMBEM GMSH
set -u
gembem=$1; gmsh=$2; dir=$(dirname "$0")
fail=0; n=0
out=$(mktemp -d)
for scene in "$dir"/bad/*.yaml; do
  name=$(basename "$scene" .yaml); n=$((n + 1))
  expect=$(cat "$dir/bad/$name.expect")
  msg=$("$gembem" run "$scene" -o "$out/$name" 2>&1 >/dev/null); code=$?
  if [ $code -ne 2 ]; then echo "FAIL $name: exit status $code, expected 2 ($msg)"; fail=$((fail + 1)); continue; fi
  case "$msg" in *"$expect"*) ;; *) echo "FAIL $name: message '$msg' lacks '$expect'"; fail=$((fail + 1)); continue;; esac
  if [ -e "$out/$name" ]; then echo "FAIL $name: the run directory was created"; fail=$((fail + 1)); continue; fi
  echo "ok   $name: $msg"
done
mkdir -p "$out/msh"
for geo in "$dir"/bad_msh/*.geo; do
  name=$(basename "$geo" .geo); n=$((n + 1))
  read -r -a args <<< "$(head -1 "$geo" | sed 's|^// gmsh: ||')"
  "$gmsh" "${args[@]}" "$geo" -o "$out/msh/$name.msh" > "$out/msh/$name.log" 2>&1 ||
    { echo "FAIL $name: gmsh could not write the mesh"; fail=$((fail + 1)); continue; }
  cp "$dir/bad_msh/$name.yaml" "$out/msh/"
  msg=$("$gembem" run "$out/msh/$name.yaml" -o "$out/$name" 2>&1 >/dev/null); code=$?
  if [ $code -ne 2 ]; then echo "FAIL $name: exit status $code, expected 2 ($msg)"; fail=$((fail + 1)); continue; fi
  lacks=""
  while IFS= read -r expect; do case "$msg" in *"$expect"*) ;; *) lacks=$expect;; esac; done < "$dir/bad_msh/$name.expect"
  if [ -n "$lacks" ]; then echo "FAIL $name: message '$msg' lacks '$lacks'"; fail=$((fail + 1)); continue; fi
  if [ -e "$out/$name" ]; then echo "FAIL $name: the run directory was created"; fail=$((fail + 1)); continue; fi
  echo "ok   $name: $msg"
done
# The good scene runs (so that the bad ones fail for their own reason).
"$gembem" run "$dir/good.yaml" -o "$out/good" --quiet || { echo "FAIL good.yaml did not run"; fail=$((fail + 1)); }
"$gembem" run "$dir/good_host.yaml" -o "$out/good_host" --quiet || { echo "FAIL good_host.yaml did not run"; fail=$((fail + 1)); }
# A host meshed coarsely against its grains runs, with the warning on stderr and in run_info.yaml.
msg=$("$gembem" run "$dir/warn_coarse_host.yaml" -o "$out/warn" --quiet 2>&1) || { echo "FAIL warn_coarse_host.yaml did not run"; fail=$((fail + 1)); }
want="warning: the host's longest cavity element (0.975452) is 2.96 mean grain radii"
case "$msg" in *"$want"*) ;; *) echo "FAIL warn_coarse_host.yaml: '$msg' lacks '$want'"; fail=$((fail + 1));; esac
grep -q "^warning: \"the host's longest cavity element" "$out/warn/run_info.yaml" 2>/dev/null ||
  { echo "FAIL warn_coarse_host.yaml: no warning in run_info.yaml"; fail=$((fail + 1)); }
grep -q "^  elements: {outer: 40, cavity: 16}" "$out/warn/run_info.yaml" 2>/dev/null ||
  { echo "FAIL warn_coarse_host.yaml: run_info.yaml lacks the .geo's own 40 + 16 elements"; fail=$((fail + 1)); }
rm -rf "$out"
echo "$((n - fail)) of $n bad scenes refused as expected"
[ $fail -eq 0 ]
