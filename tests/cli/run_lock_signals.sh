#!/usr/bin/env bash
# One writer per run directory, and signals that leave a true record (docs/run-directory.md, "One
# writer" and "Signals"), with real processes: a run in progress refuses a second writer (run with
# and without --overwrite, bem, pack: exit 2, the message naming its pid) and a --resume (exit 2),
# and ends as if they had not been tried; a run killed with SIGKILL frees its directory (the kernel
# drops the lock): --resume is allowed, lists the stop as `killed`, and the Python reader says
# `running` of the live run and `killed` of the dead one. SIGTERM, SIGINT and SIGHUP, each sent
# mid-run: exit 128 + the signal's number, one line saying so and how to resume, status
# `interrupted`, a checkpoint, no temporary file; --resume then yields the uninterrupted run's bytes.
# Output paths: up to 900 characters work, longer ones are refused (exit 2) with nothing made.
# The waits are for rows to appear (wait_rows), not fixed sleeps: a loaded machine only slows it.
set -u
source "$(dirname "$0")/resume_lib.sh"
scene=$out/scenes/ref.yaml   # the 122-disc shear, 7 steps of 1-2 thousand iterations

no_tmp() { [ -z "$(find "$1" -name '*.tmp')" ]; }
# the exit status, stderr and outcome of a command that must be refused with exit 2 and EXPECT
refused() { # LABEL EXPECT COMMAND...
  local label=$1 expect=$2 msg code; shift 2
  msg=$("$@" 2>&1 >/dev/null); code=$?
  if [ $code -eq 2 ] && [[ $msg == *"$expect"* ]]; then ok "$label: exit 2: $msg"
  else bad "$label: exit $code, message '$msg' (expected exit 2 and '$expect')"; fi
}

mkdir -p "$out/ref"
(cd "$out/ref" && "$gembem" run "$scene" -o run --quiet) || bad "the uninterrupted run failed"
cd "$out"

# One writer: the live run refuses the others, and ends as the uninterrupted run. Each case runs in
# its own folder, its run directory named run/ as the reference's (state.yaml names it).
mkdir -p "$out/live"; cd "$out/live"
"$gembem" run "$scene" -o run --quiet 2> err & pid=$!
if wait_rows run 2; then
  kill -STOP $pid   # held still (its lock with it) while the others try: no race with its end
  refused "a second run with --overwrite into a live run's directory" "pid $pid on" \
    "$gembem" run "$scene" -o run --overwrite --quiet
  refused "a second run into it" "pid $pid on" "$gembem" run "$scene" -o run --quiet
  refused "--resume of the live run" "its run is still going (pid $pid on" "$gembem" run --resume run --quiet
  refused "gembem bem --overwrite into it" "pid $pid on" \
    "$gembem" bem "$root/tests/bem/scenes/good_base.yaml" -o run --overwrite
  refused "gembem pack --overwrite into it" "pid $pid on" \
    "$gembem" pack "$root/tests/pack/box_stress.yaml" -o run --overwrite --quiet
  s=$(py_status run)
  [ "$s" = running ] && ok "Python: Run.status of the live run: $s" || bad "Python: Run.status of the live run: $s"
  kill -CONT $pid
else bad "one writer: the live run wrote no rows in 2 minutes"; fi
wait $pid; code=$?
[ $code -eq 0 ] && same_runs "$out/ref/run" run "one writer: the run that refused the others" \
  || bad "one writer: the live run exited $code: $(cat err)"
refused "--resume once it completed (its lock free, its status completed)" "nothing to resume" \
  "$gembem" run --resume run --quiet

# Killed outright: the kernel drops the lock, the directory is free for --resume.
mkdir -p "$out/dead"; cd "$out/dead"
"$gembem" run "$scene" -o run --quiet 2> /dev/null & pid=$!
if wait_rows run 2; then
  kill -KILL $pid; wait $pid 2> /dev/null
  grep -q "^status: running" run/run_info.yaml && ok "killed: run_info.yaml still says running" \
    || bad "killed: run_info.yaml: $(grep ^status: run/run_info.yaml)"
  s=$(py_status run)
  [ "$s" = killed ] && ok "Python: Run.status of the killed run (lock free): $s" || bad "Python: Run.status: $s"
  if "$gembem" run --resume run --quiet; then
    same_runs "$out/ref/run" run "killed (SIGKILL), resumed once its lock was free"
    grep -q "previous_status: killed" run/run_info.yaml && grep -q "^interrupted: 1 " run/run_info.yaml \
      && ok "killed: run_info.yaml lists the resume after a kill" \
      || bad "killed: run_info.yaml: $(grep -E 'previous_status|^interrupted' run/run_info.yaml)"
  else bad "killed: --resume refused or failed"; fi
else bad "killed: the run wrote no rows in 2 minutes"; kill -KILL $pid; fi

# SIGTERM, SIGINT, SIGHUP: a checkpoint, status interrupted, exit 128 + N, then an exact resume.
# (env --default-signal: a background job of a script starts with SIGINT ignored, which gembem keeps.)
for sig in TERM INT HUP; do
  num=$(kill -l $sig)
  mkdir -p "$out/sig_$sig"; cd "$out/sig_$sig"
  env --default-signal=$sig "$gembem" run "$scene" -o run --quiet 2> err & pid=$!
  if ! wait_rows run 3; then bad "SIG$sig: the run wrote no rows in 2 minutes"; kill -KILL $pid; continue; fi
  kill -$sig $pid; wait $pid; code=$?
  msg=$(cat err)
  if [ $code -eq $((128 + num)) ] && [ "$(wc -l < err)" -eq 1 ] && [[ $msg == *"interrupted by SIG$sig"* ]] &&
     [[ $msg == *"gembem run --resume run"* ]]; then ok "SIG$sig: exit $code: $msg"
  else bad "SIG$sig: exit $code (expected $((128 + num))), stderr '$msg'"; fi
  if grep -q "^status: interrupted" run/run_info.yaml && grep -q "^message: .*SIG$sig" run/run_info.yaml &&
     grep -q "^status: interrupted" run/.lock && [ -f run/checkpoint.txt ] && no_tmp run; then
    ok "SIG$sig: run_info.yaml and .lock say interrupted, a checkpoint, no temporary file"
  else bad "SIG$sig: $(grep -E '^(status|message)' run/run_info.yaml), checkpoint: $(ls run/checkpoint.txt 2>&1), tmp: $(find run -name '*.tmp')"; fi
  if "$gembem" run --resume run --quiet; then
    same_runs "$out/ref/run" run "SIG$sig, resumed"
    grep -q "previous_status: interrupted" run/run_info.yaml && ok "SIG$sig: the resume is listed after the interruption" \
      || bad "SIG$sig: run_info.yaml: $(grep previous_status run/run_info.yaml)"
  else bad "SIG$sig: the resume failed"; fi
done
cd "$out"

# Long output paths: a directory of 900 characters works; longer ones are refused up front.
scene_edit "$scene" -o short.yaml --set loading.0.shear_mean_stress.steps=1
long_path() { # LENGTH: a relative path of that many characters, in parts of at most 200
  local n=$1 p="" part
  while [ $n -gt 0 ]; do
    part=$((n > 201 ? 200 : n)); [ $((n - part)) -eq 1 ] && part=$((part - 1))
    p+=$(head -c $part /dev/zero | tr '\0' d); n=$((n - part))
    [ $n -gt 0 ] && { p+=/; n=$((n - 1)); }
  done
  printf %s "$p"
}
mkdir -p paths; cd paths
p=$(long_path 900)
if "$gembem" run ../short.yaml -o "$p" --quiet && [ -d "$p" ] && [ -f "$p/scene.yaml" ] && [ -f "$p/state.yaml" ]; then
  ok "an output path of ${#p} characters: run, its files in place"
else bad "an output path of ${#p} characters failed"; fi
rm -rf d*
for n in 901 1010 1023 4000; do
  p=$(long_path $n)
  refused "an output path of $n characters" "a path of $n characters" "$gembem" run ../short.yaml -o "$p" --quiet
  [ -z "$(ls)" ] && ok "$n characters: nothing made" || bad "$n characters: made $(ls)"
done
cd "$out"

finish
