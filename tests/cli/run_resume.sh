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
# OPENBLAS_NUM_THREADS=1), two hybrid scenes (a host with UMFPACK; the infinite plane with
# tangential forces on the boundary particles, CHOLMOD), and the global solver's default (the line
# search, UMFPACK) strain-controlled with `output: {localisation: false}`.
# Then what must be refused (exit 2, the run directory unchanged): a changed scene, a changed file
# the scene reads, a damaged checkpoint, a cut appended file, a completed run, no checkpoint,
# --resume with -o. And a disk that fills (a file size limit, `ulimit -f`): exit 4 naming the file,
# no temporary file left, and the run resumes from its last checkpoint to the uninterrupted result.
set -u
source "$(dirname "$0")/resume_lib.sh"
# initial_state kept relative: the refusals below copy the scene and its test_state/ elsewhere
scene_edit "$out/scenes/ref.yaml" -o "$out/scenes/ref.yaml" --set initial_state=test_state/state.yaml \
  --add 'output={snapshot_every: 3, contacts_every: 2, checkpoint_every: 3}'

kill_case reference "$out/scenes/ref.yaml" 10 25 "0.3 0.6"
kill_case global "$out/scenes/global.yaml" 8 20
kill_case global_strain "$out/scenes/global_strain.yaml" 8 20
kill_case hybrid "$out/scenes/hybrid.yaml" 8 20
kill_case hybrid_remote "$out/scenes/hybrid_remote.yaml" 8 20
# the default global solver (the line search, its smoother-first state carried from step to step)
# strain-controlled, without localisation.csv (the checkpoint's appended files without it)
scene_edit "$out/scenes/global_strain.yaml" -o "$out/scenes/line_search.yaml" --set solver.linear=umfpack \
  --add output.localisation=false
kill_case line_search "$out/scenes/line_search.yaml" 8 20
[ ! -e "$out/line_search/kill/run/localisation.csv" ] && ok "line_search: no localisation.csv" \
  || bad "line_search: localisation.csv written"

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
  csv_awk 'BEGIN { OFS = ","; CONVFMT = "%.17g" } NR == 2 { $col("x") += 1e-3 } 1' grains.orig > test_state/state_grains.csv
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
scene_edit "$root/validation/three_discs/case1.yaml" -o scene.yaml --delete output.snapshot_steps --add output.snapshot_every=0
mkdir ref cut; (cd ref && "$gembem" run ../scene.yaml -o run --quiet) || bad "disk full: the uninterrupted run failed"
cd cut
# SIGXFSZ left to its default: gembem ignores it itself, so that the write fails (EFBIG) and it says so
msg=$( (ulimit -f 24; "$gembem" run ../scene.yaml -o run --quiet) 2>&1); code=$?
rows=$(($(wc -l < run/steps.csv) - 1))
if [ $code -eq 4 ] && [[ $msg =~ "run/".*"write failed: File too large" ]] && [ "$rows" -gt 1 ] && [ "$rows" -lt 110 ]; then
  ok "disk full: exit 4 after $rows rows: $msg"
else bad "disk full: exit $code, '$msg', $rows rows"; fi
[ -z "$(find run -name '*.tmp')" ] && ok "disk full: no temporary file left" || bad "disk full: left $(find run -name '*.tmp')"
grep -q "^status: i/o error" run/run_info.yaml && ok "disk full: run_info.yaml says i/o error" \
  || bad "disk full: run_info.yaml: $(grep status: run/run_info.yaml)"
if "$gembem" run --resume run --quiet; then
  same_runs ../ref/run run "disk full"
  grep -q "previous_status: i/o error" run/run_info.yaml && ok "disk full: the resume is listed after the i/o error" \
    || bad "disk full: run_info.yaml does not list the resume"
else bad "disk full: the resume failed"; fi

finish
