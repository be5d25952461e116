# The machinery of the tests of interrupted runs (tests/cli/run_resume.sh, run_resume_within.sh),
# sourced with the gembem command as $1: runs killed with SIGKILL at seeded output writes
# (GB_TEST_KILL_AT) and resumed until they complete, compared with the uninterrupted run, and the
# scenes they run. A test may redefine on_kill (after each kill) and on_resume (before each resume
# after a kill), run in the killed run's parent directory, and set extra_env (NAME=VALUE words) for
# the killed and resumed processes.
gembem=$(cd "$(dirname "$1")" && pwd)/$(basename "$1"); root=$(cd "$(dirname "$0")/../.." && pwd)
source "$root/tests/csv.sh"
source "$root/tests/scene.sh"
source "$root/tools/lib.sh"
gb_test_begin
# The test's end: its outputs removed if it passed; its exit status.
finish() {
  cd "$out/.."
  [ $fail -eq 0 ] && rm -rf "$out" || echo "outputs kept in $out"
  echo "$passed passed, $fail failed"
  [ $fail -eq 0 ]
}
export OPENBLAS_NUM_THREADS=1

seed=12345
draw() { seed=$(( (seed * 1103515245 + 12345) % 2147483648 )); n=$(( seed / 65536 % $1 + 1 )); } # n in 1..$1

# Equal run directories (tools/lib.sh's gb_same_run_dirs: times and the lock file's holder aside).
same_runs() { # A B LABEL
  local a=$1 b=$2
  if gb_same_run_dirs "$a" "$b" "$out/diff"; then
    ok "$3: the resumed run directory equals the uninterrupted one ($(find "$a" -type f | wc -l) files)"
  else bad "$3: the run directories differ: $(head -c 600 "$out/diff")"; fi
}

# Until RUNDIR/steps.csv holds N rows (step 0 is one); 1 if it does not within 2 minutes (a loaded
# machine slows a run: the tests wait for rows, not for a time).
wait_rows() { # RUNDIR N
  local k
  for k in $(seq 1 600); do
    [ -f "$1/steps.csv" ] && [ $(($(wc -l < "$1/steps.csv") - 1)) -ge "$2" ] && return 0
    sleep 0.2
  done
  return 1
}
# Python's reading of RUNDIR's status (gembem.Run.status).
py_status() { PYTHONPATH=$root/python /usr/bin/python3 -c 'import sys, gembem; print(gembem.Run(sys.argv[1]).status)' "$1"; }

# One scene: uninterrupted in $d/ref/run, interrupted and resumed in $d/kill/run.
# run/ completed (a kill may land after run_info.yaml says so: nothing to resume then)
done_() { grep -qs "^status: completed" run/run_info.yaml; }

# gembem run ARGS, killed at its n-th write (GB_TEST_KILL_AT=$n; 0: never); its exit status.
extra_env=
start() { (env GB_TEST_KILL_AT=$n $extra_env "$gembem" run "$@" --quiet; exit $?) 2>/dev/null; }
on_kill() { :; }
on_resume() { :; }

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
      # a resume's first write is its own line in run_info.yaml: killed there, it is not a resume
      # that run_info can list (the checks count the resumes that ran)
      [ "$n" -eq 1 ] && n=2
      on_resume; start --resume run; rc=$?; resumes=$((resumes + 1))
    else start "$scene" -o run --overwrite; rc=$?; starts=$((starts + 1)); fi
    [ $rc -eq 137 ] && { kills=$((kills + 1)); on_kill; }
    [ $rc -eq 0 ] && break
    [ $rc -ne 137 ] && done_ && break
    [ $rc -ne 137 ] && { bad "$name: attempt $attempt (kill at $n) exited $rc"; cd "$out"; return; }
  done
  n=0
  while [ $rc -ne 0 ] && ! done_; do  # to the end
    if [ -f run/checkpoint.txt ]; then on_resume; start --resume run; rc=$?; resumes=$((resumes + 1))
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
  items=$(grep -c "^  - {at: .*previous_status: killed" "$info")
  if grep -q "^status: completed" "$info" && [ "$items" -ge 1 ] && grep -q "^interrupted: $items " "$info"; then
    ok "$name: run_info.yaml: completed, killed $items times, each resume listed as after a kill"
  else bad "$name: run_info.yaml: $(grep -E '^(status|interrupted):' "$info" | tr '\n' ' '), $items resumes listed"; fi
}

# The scenes, written next to the files they read (initial_state: the copy of test_state/ here,
# which run_resume.sh changes to see a resume refused).
mkdir -p "$out/scenes"
cp -r "$root/validation/biaxial122/test_state" "$out/scenes/"
shear=$root/validation/biaxial122/test_shear.yaml   # loading: 0 shear_mean_stress (20 steps)
scene_edit "$shear" -o "$out/scenes/ref.yaml" --set initial_state=test_state/state.yaml \
  --set loading.0.shear_mean_stress.steps=7
scene_edit "$shear" -o "$out/scenes/global.yaml" --set initial_state=test_state/state.yaml \
  --add solver.method=global --add solver.linear=cholmod --set loading.0.shear_mean_stress.steps=7
# strain-controlled: the pair list is rebuilt within steps, and sliding contacts are held stuck across them
scene_edit "$shear" -o "$out/scenes/global_strain.yaml" --set initial_state=test_state/state.yaml \
  --add solver.method=global --add solver.linear=cholmod \
  --set 'loading.0={strain: {de1: 0.0006, de2: -0.0006, steps: 4}}'
scene_edit "$root/tests/hybrid/load_grains.yaml" -o "$out/scenes/hybrid.yaml"
scene_edit "$root/tests/hybrid/load_grains_remote.yaml" -o "$out/scenes/hybrid_remote.yaml" --set solver.linear=cholmod \
  --set 'materials.grain_boundary={kn: 1000, kt: 500, friction_deg: 20}'
