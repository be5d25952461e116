#!/usr/bin/env bash
# Every scene in tests/cli/bad is refused before any computation: exit status 2, a message with
# the expected file:line:column and text (the .expect file beside it), and no run directory.
# The scenes of tests/cli/bad_msh read the .msh that gmsh writes of the .geo beside them (its
# first line gives gmsh's arguments), made at test time: each line of their .expect must appear.
# The scenes of tests/cli/fail start and stop at a step that does not converge: exit status 3 and
# the .expect's text (what to change); the change their "# fix: SED" line makes then runs. The
# scenes of tests/cli/warn run, with the .expect's warning on stderr and in run_info.yaml. The
# .expect files hold the hints, so that a hint lost fails the test (docs/troubleshooting.md).
# Every position in an .expect is counted from the test file as an editor does (1-based line, 1-based
# column of the offending token's first character: a quoted scalar's opening quote, a duplicate
# key's second occurrence), not copied from gembem's output; where it is not obvious, the test
# file says how in a comment (an awk one-liner that prints the column).
#   run_bad_scenes.sh GEMBEM GMSH
set -u
gembem=$1; gmsh=$2; dir=$(dirname "$0")
source "$dir/../../tools/lib.sh"
source "$dir/../scene.sh"
fail=0; n=0
out=$(mktemp -d)
for scene in "$dir"/bad/*.yaml; do expect_refused run "$scene" "$(cat "${scene%.yaml}.expect")"; done
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
for scene in "$dir"/fail/*.yaml; do
  name=$(basename "$scene" .yaml); n=$((n + 1))
  expect=$(cat "$dir/fail/$name.expect")
  msg=$("$gembem" run "$scene" -o "$out/$name" --quiet 2>&1 >/dev/null); code=$?
  if [ $code -ne 3 ]; then echo "FAIL $name: exit status $code, expected 3 ($msg)"; fail=$((fail + 1)); continue; fi
  case "$msg" in *"$expect"*) ;; *) echo "FAIL $name: message '$msg' lacks '$expect'"; fail=$((fail + 1)); continue;; esac
  sed "$(sed -n 's/^# fix: //p' "$scene")" "$scene" > "$out/$name.fixed.yaml"
  cmp -s "$scene" "$out/$name.fixed.yaml" && { echo "FAIL $name: its fix changes nothing"; fail=$((fail + 1)); continue; }
  "$gembem" run "$out/$name.fixed.yaml" -o "$out/$name.fixed" --quiet ||
    { echo "FAIL $name: the scene with the change the message asks for does not run"; fail=$((fail + 1)); continue; }
  echo "ok   $name: $msg; fixed, it runs"
done
for scene in "$dir"/warn/*.yaml; do
  name=$(basename "$scene" .yaml); n=$((n + 1))
  expect=$(cat "$dir/warn/$name.expect")
  msg=$("$gembem" run "$scene" -o "$out/$name" --quiet 2>&1 >/dev/null); code=$?
  if [ $code -ne 0 ]; then echo "FAIL $name: exit status $code, expected 0 ($msg)"; fail=$((fail + 1)); continue; fi
  case "$msg" in *"$expect"*) ;; *) echo "FAIL $name: stderr '$msg' lacks '$expect'"; fail=$((fail + 1)); continue;; esac
  grep -qF "${expect#warning: }" "$out/$name/run_info.yaml" ||
    { echo "FAIL $name: run_info.yaml lacks the warning"; fail=$((fail + 1)); continue; }
  echo "ok   $name: $msg"
done
# A stress that frictionless walls cannot reach under the grains' weight (src/run/program.c,
# gb_run_weight_reachable): two discs of radius 1 weighing 1.5e5 dyn/cm^2 of area each in a box 4 wide,
# whose mean vertical wall stress is at least 2 pi 1.5e5 / (2 4) - 100 / 4 = 117 785 dyn/cm: its
# first step's 7.5e4 is refused at once (exit 2), the initial state kept; 1.5e4 of weight runs.
n=$((n + 1))
sed 's/^solver:/body_force: {weight_per_area: 1.5e5}\nsolver:/' "$dir/good.yaml" > "$out/heavy.yaml"
msg=$("$gembem" run "$out/heavy.yaml" -o "$out/heavy" --quiet 2>&1 >/dev/null); code=$?
want="loading[0].isotropic: the walls cannot reach s1 75000 and s2 75000 dyn/cm under the grains' weight (0, -942478 dyn)"
if [ $code -ne 2 ]; then echo "FAIL heavy: exit status $code, expected 2 ($msg)"; fail=$((fail + 1))
elif case "$msg" in *"$want"*"s1 >= 117785"*) false;; *) true;; esac; then echo "FAIL heavy: message '$msg' lacks '$want'"; fail=$((fail + 1))
elif [ "$(wc -l < "$out/heavy/steps.csv")" != 2 ]; then echo "FAIL heavy: steps.csv should hold the initial state"; fail=$((fail + 1))
else echo "ok   heavy: $msg"; fi
sed 's/^solver:/body_force: {weight_per_area: 1.5e4}\nsolver:/' "$dir/good.yaml" > "$out/light.yaml"
"$gembem" run "$out/light.yaml" -o "$out/light" --quiet || { echo "FAIL light.yaml (1.5e4 of weight) did not run"; fail=$((fail + 1)); }
# The good scene runs (so that the bad ones fail for their own reason).
"$gembem" run "$dir/good.yaml" -o "$out/good" --quiet || { echo "FAIL good.yaml did not run"; fail=$((fail + 1)); }
"$gembem" run "$dir/good_host.yaml" -o "$out/good_host" --quiet || { echo "FAIL good_host.yaml did not run"; fail=$((fail + 1)); }
# A host meshed coarsely against its grains runs, with the warning on stderr and in run_info.yaml.
msg=$("$gembem" run "$dir/warn_coarse_host.yaml" -o "$out/warn" --quiet 2>&1) || { echo "FAIL warn_coarse_host.yaml did not run"; fail=$((fail + 1)); }
want="warning: the host's longest cavity element (0.975452) is 2.96 mean grain radii (0.33) long, more than 2.5: \
grains sit in notches between its boundary particles up to 0.49 of a radius deep; give the cavity more elements: \
host.elements: {cavity: 24} (elements of 2 mean radii)"
case "$msg" in *"$want"*) ;; *) echo "FAIL warn_coarse_host.yaml: '$msg' lacks '$want'"; fail=$((fail + 1));; esac
grep -q "^warning: \"the host's longest cavity element" "$out/warn/run_info.yaml" 2>/dev/null ||
  { echo "FAIL warn_coarse_host.yaml: no warning in run_info.yaml"; fail=$((fail + 1)); }
grep -q "^  elements: {outer: 40, cavity: 16}" "$out/warn/run_info.yaml" 2>/dev/null ||
  { echo "FAIL warn_coarse_host.yaml: run_info.yaml lacks the .geo's own 40 + 16 elements"; fail=$((fail + 1)); }
# With the cavity elements that the warning asks for, no warning of its elements (the run's other warnings may remain).
scene_edit "$dir/warn_coarse_host.yaml" -o "$out/fine_host.yaml" --add 'host.elements={outer: 40, cavity: 24}'
msg=$("$gembem" run "$out/fine_host.yaml" -o "$out/fine" --quiet 2>&1) || { echo "FAIL fine_host.yaml did not run"; fail=$((fail + 1)); }
case "$msg" in *"longest cavity element"*) echo "FAIL the cavity with the elements asked for still warns: $msg"; fail=$((fail + 1));; esac
rm -rf "$out"
echo "$((n - fail)) of $n bad, failing and warned scenes as expected"
[ $fail -eq 0 ]
