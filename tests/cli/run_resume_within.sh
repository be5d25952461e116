#!/usr/bin/env bash
# Checkpoints within a load step (docs/run-directory.md, "Checkpoints and resume"): runs whose steps take tens to
# thousands of iterations, with a checkpoint every N iterations (the test hook
# GB_TEST_CHECKPOINT_ITERATIONS=N instead of output.checkpoint_minutes, so that no clock decides),
# killed with SIGKILL at seeded output writes (GB_TEST_KILL_AT: history.csv rows, the checkpoints
# themselves, the steps' rows and files) and resumed until they complete (tests/cli/resume_lib.sh);
# the run directories must equal the uninterrupted run's, which took no checkpoint within a step.
# Before each resume the checkpoint is read: the test counts the resumes from within a step and
# fails if there are too few, so that it cannot pass with kills that all fell between steps; and
# it requires, per scene, the places the issue names:
#  - ref_history: the 122-disc shear_mean_stress (reference iteration, 1 500-3 200 iterations a step,
#    solver.history on, so that kills land at any iteration): resumes in the second relaxation
#    (mean-stress control) of a step;
#  - cutback: the same with max_iterations 1 200, so that every step is cut back (2 to 4 sub-steps,
#    no history: most writes are checkpoints): resumes inside a cut-back sub-step (h < 1), resumes
#    inside an attempt that later fails and is undone (the sub-step's start read from the
#    checkpoint), and kills during a checkpoint's own writing within a step;
#  - global_cutback: the same shear with the global solver (CHOLMOD, damped Newton) and
#    max_iterations 60: 56-330 iterations a step, steps 2 and 4 cut back into 5 and 3 sub-steps
#    (a failed attempt restores a sub-step's start whose pair list may be the one the solver's
#    pattern was built for: the checkpoint keeps which lists are the same); resumes inside a
#    cut-back sub-step and inside an attempt that then fails;
#  - hybrid_history: a host (UMFPACK) with grains in its cavity, host_load stages (the host's load
#    increment is applied once, before the checkpoint), solver.history on;
#  - hybrid_followed: the same host following its boundary (host.updated_lagrangian: every 2 steps):
#    resumes within a step after a rebase (the checkpoint's moved mesh, from which G, H and K are
#    recomputed), and kills between steps where the resumed run must rebase where the first would.
# A checkpoint of format 6 (before hosts followed their boundary) still resumes, to the same result.
set -u
source "$(dirname "$0")/resume_lib.sh"

steps4=(--set loading.0.shear_mean_stress.steps=4)   # of 7 in resume_lib.sh's ref and global
scene_edit "$out/scenes/ref.yaml" -o "$out/scenes/ref_history.yaml" --add solver.history=true "${steps4[@]}"
scene_edit "$out/scenes/ref.yaml" -o "$out/scenes/cutback.yaml" --set solver.max_iterations=1200 "${steps4[@]}"
scene_edit "$out/scenes/hybrid.yaml" -o "$out/scenes/hybrid_history.yaml" --add solver.history=true
scene_edit "$out/scenes/hybrid_history.yaml" -o "$out/scenes/hybrid_followed.yaml" \
  --add 'host.updated_lagrangian={every: 2}'
scene_edit "$out/scenes/global.yaml" -o "$out/scenes/global_cutback.yaml" --set solver.max_iterations=60 "${steps4[@]}"

# Before a resume: the checkpoint's step in progress, if any, as "STEP H CUTS PHASE" in $d/within.
on_resume() {
  grep -q "^within_step 1" run/checkpoint.txt || return 0
  awk '$1 == "step" { s = $4; h = $8 } $1 == "progress" { print s, h, $2, $5 }' run/checkpoint.txt >> "$d/within"
}
# After a kill: killed while writing a checkpoint within a step (its temporary file is whole).
on_kill() {
  grep -qs "^within_step 1" run/checkpoint.txt.tmp && echo >> "$d/in_write"
  return 0
}
count() { [ -f "$1" ] && wc -l < "$1" || echo 0; }

# NAME EVERY ATTEMPTS MAX_N MIN_RESUMES: kill_case with a checkpoint every EVERY iterations, and at
# least MIN_RESUMES resumes from within a step.
within_case() {
  local name=$1 d=$out/$1
  extra_env="GB_TEST_CHECKPOINT_ITERATIONS=$2"
  kill_case "$name" "$out/scenes/$name.yaml" "$3" "$4"
  local k=$(count "$d/within")
  [ "$k" -ge "$5" ] && ok "$name: $k resumes from within a step" \
    || bad "$name: $k resumes from within a step, expected $5 or more"
  local listed=$(grep -c "within_step: true, iterations_done: [1-9]" "$d/kill/run/run_info.yaml")
  [ "$listed" = "$k" ] && ok "$name: run_info.yaml lists the $k resumes within a step" \
    || bad "$name: run_info.yaml lists $listed resumes within a step, expected $k"
}

# NAME: resumes inside a cut-back sub-step (h < 1), and inside a whole step's attempt (h = 1) in a
# step that the uninterrupted run cut back: an attempt that then failed and was undone.
substep_resumes() {
  local k=$(awk '$2 != "0x1p+0"' "$out/$1/within" 2>/dev/null | wc -l)
  [ "$k" -ge 1 ] && ok "$1: $k resumes inside a cut-back sub-step" || bad "$1: no resume inside a cut-back sub-step"
  k=$(csv_awk 'FNR == NR { s[$col("step")] = $col("substeps"); next } { split($0, w, " ") } w[2] == "0x1p+0" && s[w[1]] > 1' \
    "$out/$1/ref/run/steps.csv" "$out/$1/within" 2>/dev/null | wc -l)
  [ "$k" -ge 1 ] && ok "$1: $k resumes inside an attempt that then failed and was undone" \
    || bad "$1: no resume inside an attempt that later failed"
}

within_case ref_history 400 12 1500 4
k=$(awk '$4 == 2' "$out/ref_history/within" 2>/dev/null | wc -l)
[ "$k" -ge 1 ] && ok "ref_history: $k resumes in a step's second relaxation (mean stress)" \
  || bad "ref_history: no resume in a step's second relaxation"

within_case cutback 150 14 60 4
substep_resumes cutback
k=$(count "$out/cutback/in_write")
[ "$k" -ge 1 ] && ok "cutback: $k kills while a checkpoint within a step was being written" \
  || bad "cutback: no kill while a checkpoint within a step was being written"

within_case global_cutback 3 10 50 4
substep_resumes global_cutback
within_case hybrid_history 1 12 25 4
mkdir -p "$out/hybrid_followed"; : > "$out/hybrid_followed/rebased"
on_resume() {
  grep -q "^within_step 1" run/checkpoint.txt || return 0
  grep -q "^followed [1-9]" run/checkpoint.txt && echo >> "$d/rebased"
  awk '$1 == "step" { s = $4; h = $8 } $1 == "progress" { print s, h, $2, $5 }' run/checkpoint.txt >> "$d/within"
}
within_case hybrid_followed 1 12 25 4
k=$(count "$out/hybrid_followed/rebased")
[ "$k" -ge 2 ] && ok "hybrid_followed: $k resumes within a step of a rebased host" \
  || bad "hybrid_followed: $k resumes within a step of a rebased host, expected 2 or more"

# A checkpoint of format 1 (before checkpoints within steps), its checksum made right: refused.
d=$out/format1; mkdir -p "$d"; cd "$d"
n=30; extra_env="GB_TEST_CHECKPOINT_ITERATIONS=7"; start "$out/scenes/global.yaml" -o run
if [ -f run/checkpoint.txt ]; then
  fmt=$(awk 'NR == 1 { print $2 }' run/checkpoint.txt)
  /usr/bin/python3 - run/checkpoint.txt "$fmt" <<'PY'
import sys
text = open(sys.argv[1], 'rb').read()
body = text[:text.rindex(b'end ')].replace(b'gembem_checkpoint ' + sys.argv[2].encode(), b'gembem_checkpoint 1', 1)
h = 0xcbf29ce484222325
for b in body: h = ((h ^ b) * 0x100000001b3) % 2**64
open(sys.argv[1], 'wb').write(body + b'end %016x\n' % h)
PY
  msg=$("$gembem" run --resume run 2>&1 >/dev/null); code=$?
  [ $code -eq 2 ] && [[ $msg =~ "a checkpoint of format 1, this gembem reads formats 6 to $fmt" ]] && ok "format 1: refused: $msg" \
    || bad "format 1: exit $code, '$msg'"
else bad "format 1: the run left no checkpoint"; fi

# A checkpoint of format 6 (a host at rest, without the "followed" line) resumes to the
# uninterrupted run's result.
d=$out/format6; mkdir -p "$d"; cd "$d"
n=20; extra_env="GB_TEST_CHECKPOINT_ITERATIONS=1"; start "$out/scenes/hybrid_history.yaml" -o run
if grep -qs "^followed 0 0$" run/checkpoint.txt; then
  fmt=$(awk 'NR == 1 { print $2 }' run/checkpoint.txt)
  /usr/bin/python3 - run/checkpoint.txt "$fmt" <<'PY'
import sys
text = open(sys.argv[1], 'rb').read()
body = text[:text.rindex(b'end ')].replace(b'gembem_checkpoint ' + sys.argv[2].encode(), b'gembem_checkpoint 6', 1)
body = body.replace(b'\nfollowed 0 0\n', b'\n', 1)
h = 0xcbf29ce484222325
for b in body: h = ((h ^ b) * 0x100000001b3) % 2**64
open(sys.argv[1], 'wb').write(body + b'end %016x\n' % h)
PY
  "$gembem" run --resume run --quiet && same_runs "$out/hybrid_history/ref/run" "$d/run" "format 6" \
    || bad "format 6: the resume failed"
else bad "format 6: the run left no checkpoint of a host at rest"; fi

finish
