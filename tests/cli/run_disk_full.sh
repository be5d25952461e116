#!/usr/bin/env bash
# A disk that fills under a run (docs/run-directory.md, "Signals, limits and full disks"): a tmpfs
# of 2 MB holds the run directory; once the run has checkpointed, a filler takes every free byte.
# The run must stop with exit 4 and a message naming the file and "No space left on device", leave
# no temporary file, and record how it ended although run_info.yaml (rewritten through a new file)
# cannot be: the lock file, rewritten in place, says `i/o error` (and so does Python's Run.status).
# Once the filler is gone, --resume lists the stop as `i/o error`, not as a kill, and ends with the
# uninterrupted run's bytes. Mounting needs root (or a user namespace): skipped (exit 77) otherwise.
set -u
source "$(dirname "$0")/resume_lib.sh"
scene=$out/scenes/ref.yaml
mnt=$out/mnt; mkdir -p "$mnt"
if ! mount -t tmpfs -o size=2m gembem_test "$mnt" 2> "$out/mount.err"; then
  echo "skipped: cannot mount a small tmpfs here ($(cat "$out/mount.err")); needs root"
  rm -rf "$out"; exit 77
fi
trap 'umount "$mnt" 2> /dev/null' EXIT

mkdir -p "$out/ref"
(cd "$out/ref" && "$gembem" run "$scene" -o run --quiet) || bad "the uninterrupted run failed"
cd "$mnt"
"$gembem" run "$scene" -o run --quiet 2> "$out/run.err" & pid=$!
if wait_rows run 2 && [ -f run/checkpoint.txt ]; then
  kill -STOP $pid   # held still while the disk fills: it cannot end first
  dd if=/dev/zero of=filler bs=4k 2> /dev/null   # until the disk is full
  kill -CONT $pid; wait $pid; code=$?
  msg=$(cat "$out/run.err")
  if [ $code -eq 4 ] && [[ $msg == *"run/"*"No space left on device"* ]]; then ok "disk full: exit 4: $msg"
  else bad "disk full: exit $code, '$msg'"; fi
  [ -z "$(find run -name '*.tmp')" ] && ok "disk full: no temporary file left" \
    || bad "disk full: left $(find run -name '*.tmp')"
  info=$(grep ^status: run/run_info.yaml); lock=$(grep ^status: run/.lock | tr -s ' ')
  if [[ $lock == "status: i/o error" ]] && [[ $info == "status: running" || $info == "status: i/o error" ]]; then
    ok "disk full: run_info.yaml '$info', the lock file '$lock'"
  else bad "disk full: run_info.yaml '$info', the lock file '$lock'"; fi
  s=$(py_status run)
  [ "$s" = "i/o error" ] && ok "Python: Run.status: $s" || bad "Python: Run.status: $s"
  rm -f filler
  if "$gembem" run --resume run --quiet; then
    same_runs "$out/ref/run" run "disk full, resumed once space was freed"
    if grep -q "previous_status: i/o error" run/run_info.yaml && grep -q "^interrupted: 0 " run/run_info.yaml; then
      ok "disk full: the resume is listed after an i/o error, not a kill"
    else bad "disk full: run_info.yaml: $(grep -E 'previous_status|^interrupted' run/run_info.yaml)"; fi
  else bad "disk full: the resume failed"; fi
else bad "disk full: the run wrote no checkpoint in 2 minutes"; kill -KILL $pid; fi
cd "$out"
umount "$mnt"
finish
