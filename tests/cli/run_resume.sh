#!/usr/bin/env bash
# Checkpoints and resume (src/io/checkpoint.c, docs/run-directory.md "Checkpoints and resume"). Per scene: the
# run once uninterrupted, and once killed with SIGKILL again and again, each time resumed with
# `gembem run --resume` (or started again when no checkpoint existed yet), until it completes. The
# kills land at GB_TEST_KILL_AT=N, the N-th output write of the process (an appended row, which it
# tears first, or an atomic file before its rename: every output, the checkpoint itself
# included), N drawn by a seeded generator; two more land after a wall-clock delay, wherever the
# run then is. The two run directories must be equal file for file, byte for byte: steps.csv but
# for its `seconds` column (wall time), run_info.yaml aside, which must say how often the run was
# interrupted and resumed. Scenes: the 122-disc biaxial shear (reference iteration, snapshots and
# contacts files, a checkpoint every 3 steps only), the same with the global solver (CHOLMOD,
# OPENBLAS_NUM_THREADS=1), and two hybrid scenes (a host with UMFPACK; the infinite plane with
# tangential forces on the boundary particles, CHOLMOD).
# Then what must be refused (exit 2, the run directory unchanged): a changed scene, a changed file
# the scene reads, a damaged checkpoint, a cut appended file, a completed run, no checkpoint,
# --resume with -o. And a disk that fills (a file size limit, `ulimit -f`, SIGXFSZ ignored):
# exit 4, and the run resumes from its last checkpoint to the uninterrupted result.
set -u
gembem=$(cd "$(dirname "$1")" && pwd)/$(basename "$1"); root=$(cd "$(dirname "$0")/../.." && pwd)
out=$(mktemp -d); fail=0; passed=0
ok() { passed=$((passed + 1)); echo "ok   $1"; }
bad() { fail=$((fail + 1)); echo "FAIL $1"; }
export OPENBLAS_NUM_THREADS=1

seed=12345
draw() { seed=$(( (seed * 1103515245 + 12345) % 2147483648 )); n=$(( seed / 65536 % $1 + 1 )); } # n in 1..$1

# Equal run directories: every file (run_info.yaml aside), steps.csv without its seconds column.
same_runs() { # A B LABEL
  local a=$1 b=$2
  if diff -r -x run_info.yaml -x steps.csv "$a" "$b" > "$out/diff" &&
     cmp -s <(cut -d, -f1-11,13- "$a/steps.csv") <(cut -d, -f1-11,13- "$b/steps.csv"); then
    ok "$3: the resumed run directory equals the uninterrupted one ($(find "$a" -type f | wc -l) files)"
  else bad "$3: the run directories differ: $(head -c 600 "$out/diff")"; fi
}

# One scene: uninterrupted in $d/ref/run, interrupted and resumed in $d/kill/run.
# run/ completed (a kill may land after run_info.yaml says so: nothing to resume then)
done_() { grep -qs "^status: completed" run/run_info.yaml; }

# gembem run ARGS, killed at its n-th write (GB_TEST_KILL_AT=$n; 0: never); its exit status.
start() { (GB_TEST_KILL_AT=$n "$gembem" run "$@" --quiet; exit $?) 2>/dev/null; }

# One scene: uninterrupted in $d/ref/run, killed `attempts` times at its n-th write (n drawn from
# 1 to max_n) and resumed in $d/kill/run, killed after each delay and resumed in $d/timed_T/run.
kill_case() { # NAME SCENE ATTEMPTS MAX_N [TIMED_DELAYS]
  local name=$1 scene=$2 attempts=$3 maxn=$4 delays=${5:-} d=$out/$1 kills=0 resumes=0 starts=0 rc=1 n
  mkdir -p "$d/ref" "$d/kill"
  (cd "$d/ref" && "$gembem" run "$scene" -o run --quiet) || { bad "$name: the uninterrupted run failed"; return; }
  cd "$d/kill"
  for attempt in $(seq 1 "$attempts"); do  # killed at the n-th write
    draw "$maxn"
    if [ -f run/checkpoint.txt ]; then
      start --resume run; rc=$?; resumes=$((resumes + 1))
    else start "$scene" -o run --overwrite; rc=$?; starts=$((starts + 1)); fi
    [ $rc -eq 137 ] && kills=$((kills + 1))
    [ $rc -eq 0 ] && break
    [ $rc -ne 137 ] && done_ && break
    [ $rc -ne 137 ] && { bad "$name: attempt $attempt (kill at $n) exited $rc"; cd "$out"; return; }
  done
  n=0
  while [ $rc -ne 0 ] && ! done_; do  # to the end
    if [ -f run/checkpoint.txt ]; then start --resume run; rc=$?; resumes=$((resumes + 1))
    else start "$scene" -o run --overwrite; rc=$?; starts=$((starts + 1)); fi
    [ $rc -ne 0 ] && { bad "$name: the last resume exited $rc"; cd "$out"; return; }
  done
  cd "$out"
  for t in $delays; do  # a kill at a time: wherever the run is (an iteration, a write)
    mkdir -p "$d/timed_$t"; cd "$d/timed_$t"
    (timeout -s KILL "$t" "$gembem" run "$scene" -o run --quiet; exit $?) 2>/dev/null; rc=$?
    [ $rc -eq 137 ] && kills=$((kills + 1))
    while [ $rc -ne 0 ] && ! done_; do
      if [ -f run/checkpoint.txt ]; then "$gembem" run --resume run --quiet; rc=$?; resumes=$((resumes + 1))
      else "$gembem" run "$scene" -o run --overwrite --quiet; rc=$?; starts=$((starts + 1)); fi
      [ $rc -ne 0 ] && { bad "$name: resuming after a kill at ${t}s exited $rc"; break; }
    done
    cd "$out"
    same_runs "$d/ref/run" "$d/timed_$t/run" "$name, killed after ${t}s"
  done
  cd "$out"
  [ $kills -ge 3 ] && ok "$name: killed $kills times ($starts starts, $resumes resumes)" \
    || bad "$name: only $kills kills ($starts starts, $resumes resumes): the test proves little"
  same_runs "$d/ref/run" "$d/kill/run" "$name"
  local info=$d/kill/run/run_info.yaml items
  items=$(grep -c "^  - {at: .*previous_status: interrupted" "$info")
  if grep -q "^status: completed" "$info" && [ "$items" -ge 1 ] && grep -q "^interrupted: $items " "$info"; then
    ok "$name: run_info.yaml: completed, interrupted $items times, each resume listed"
  else bad "$name: run_info.yaml: $(grep -E '^(status|interrupted):' "$info" | tr '\n' ' '), $items resumes listed"; fi
}

# The scenes, written next to the files they read.
mkdir -p "$out/scenes"
cp -r "$root/validation/biaxial122/test_state" "$out/scenes/"
sed -e 's/steps: 20/steps: 7/' "$root/validation/biaxial122/test_shear.yaml" > "$out/scenes/ref.yaml"
printf 'output: {snapshot_every: 3, contacts_every: 2, checkpoint_every: 3}\n' >> "$out/scenes/ref.yaml"
sed -e 's/solver: {/solver: {method: global, linear: cholmod, /' -e 's/steps: 20/steps: 7/' \
  "$root/validation/biaxial122/test_shear.yaml" > "$out/scenes/global.yaml"
# strain-controlled: the pair list is rebuilt within steps, and sliding contacts are held stuck across them
sed -e 's/solver: {/solver: {method: global, linear: cholmod, /' \
  -e 's/  - shear_mean_stress: .*/  - strain: {de1: 0.0006, de2: -0.0006, steps: 4}/' \
  "$root/validation/biaxial122/test_shear.yaml" > "$out/scenes/global_strain.yaml"
sed -e "s|\.\./\.\./meshes|$root/meshes|" "$root/tests/hybrid/load_grains.yaml" > "$out/scenes/hybrid.yaml"
sed -e "s|\.\./\.\./meshes|$root/meshes|" -e 's/linear: umfpack/linear: cholmod/' \
  -e 's/grain_boundary: {kn: 1000, kt: 0, friction_deg: 0}/grain_boundary: {kn: 1000, kt: 500, friction_deg: 20}/' \
  "$root/tests/hybrid/load_grains_remote.yaml" > "$out/scenes/hybrid_remote.yaml"

kill_case reference "$out/scenes/ref.yaml" 10 25 "0.3 0.6"
kill_case global "$out/scenes/global.yaml" 8 20
kill_case global_strain "$out/scenes/global_strain.yaml" 8 20
kill_case hybrid "$out/scenes/hybrid.yaml" 8 20
kill_case hybrid_remote "$out/scenes/hybrid_remote.yaml" 8 20

# What is refused: exit 2, a message, the run directory untouched.
d=$out/refuse; mkdir -p "$d"; cp "$out/scenes/ref.yaml" "$d/scene.yaml"; cp -r "$out/scenes/test_state" "$d/"
cd "$d"
n=40; start scene.yaml -o run
sum() { find run -type f -print0 | sort -z | xargs -0 cat | cksum; }
refuse() { # LABEL REGEX ARGS...
  local label=$1 re=$2 before msg code; shift 2
  before=$(sum)
  msg=$("$gembem" "$@" 2>&1 >/dev/null); code=$?
  if [ $code -eq 2 ] && [[ $msg =~ $re ]] && [ "$(sum)" = "$before" ]; then ok "$label: refused: $msg"
  else bad "$label: exit $code, '$msg' (expected 2 and /$re/), directory $([ "$(sum)" = "$before" ] && echo unchanged || echo CHANGED)"; fi
}
if [ -f run/checkpoint.txt ] && grep -q "^status: running" run/run_info.yaml; then
  cp scene.yaml scene.orig
  echo "# a comment" >> scene.yaml
  refuse "a changed scene" "scene .*scene.yaml .*has changed since the run started" run --resume run
  cp scene.orig scene.yaml
  cp test_state/state_grains.csv grains.orig
  awk -F, 'BEGIN { OFS = ","; CONVFMT = "%.17g" } NR == 2 { $1 += 1e-3 } 1' grains.orig > test_state/state_grains.csv
  refuse "a changed grains file of the initial state" "has changed since the run started" run --resume run
  cp grains.orig test_state/state_grains.csv
  cp run/checkpoint.txt ck.orig
  sed -i '12s/0x1/0x2/' run/checkpoint.txt
  refuse "a damaged checkpoint" "checkpoint.txt: not a complete gembem checkpoint" run --resume run
  cp ck.orig run/checkpoint.txt
  cp run/steps.csv steps.orig
  head -c 300 steps.orig > run/steps.csv
  refuse "steps.csv cut shorter than the checkpoint" "steps.csv: missing or shorter than its checkpoint records" run --resume run
  cp steps.orig run/steps.csv
  refuse "--resume with -o" "no -o, no --overwrite" run --resume run -o other
  refuse "a directory that does not exist" "nowhere: no such run directory" run --resume nowhere
  mkdir -p empty
  refuse "a directory without a checkpoint" "empty: no checkpoint.txt to resume from" run --resume empty
  "$gembem" run --resume run --quiet && ok "the interrupted run resumes once the files are back" || bad "the resume failed"
  refuse "a completed run" "the run completed .*nothing to resume" run --resume run
  [ ! -e run/checkpoint.txt ] && ok "a completed run keeps no checkpoint" || bad "a completed run kept its checkpoint"
else bad "the run to refuse resumes of was not interrupted mid-way"; fi

# A disk that fills: the file size limit stops micromechanics.csv at 24 KB (step 50 of 110).
d=$out/full; mkdir -p "$d"; cd "$d"
sed -e 's/snapshot_steps: \[10, 110\]/snapshot_every: 0/' "$root/validation/three_discs/case1.yaml" > scene.yaml
mkdir ref cut; (cd ref && "$gembem" run ../scene.yaml -o run --quiet) || bad "disk full: the uninterrupted run failed"
cd cut
msg=$( (trap '' XFSZ; ulimit -f 24; "$gembem" run ../scene.yaml -o run --quiet) 2>&1); code=$?
rows=$(($(wc -l < run/steps.csv) - 1))
if [ $code -eq 4 ] && [[ $msg =~ "write failed" ]] && [ "$rows" -gt 1 ] && [ "$rows" -lt 110 ]; then
  ok "disk full: exit 4 after $rows rows: $msg"
else bad "disk full: exit $code, '$msg', $rows rows"; fi
grep -q "^status: i/o error" run/run_info.yaml && ok "disk full: run_info.yaml says i/o error" \
  || bad "disk full: run_info.yaml: $(grep status: run/run_info.yaml)"
if "$gembem" run --resume run --quiet; then
  same_runs ../ref/run run "disk full"
  grep -q "previous_status: i/o error" run/run_info.yaml && ok "disk full: the resume is listed after the i/o error" \
    || bad "disk full: run_info.yaml does not list the resume"
else bad "disk full: the resume failed"; fi

cd "$out/.."
[ $fail -eq 0 ] && rm -rf "$out" || echo "outputs kept in $out"
echo "$passed passed, $fail failed"
[ $fail -eq 0 ]
