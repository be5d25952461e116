#!/usr/bin/env bash
# The summary of a resumed run counts the steps that ran in it: validation/three_discs/case1.yaml
# (10 + 100 = 110 load steps) killed at its 300th output write (GB_TEST_KILL_AT), then resumed.
# The resume's summary says S + K = 110: K steps done, resumed after step S, S being run_info.yaml's
# `after_step` of the resume; and an uninterrupted run's says 110 steps.
#   run_resume_summary.sh GEMBEM
set -u
gembem=$1; root=$(cd "$(dirname "$0")/../.." && pwd)
out=$(mktemp -d); fail=0
trap 'rm -rf "$out"' EXIT
cd "$out"
scene=$root/validation/three_discs/case1.yaml
said=$("$gembem" run "$scene" -o whole) || { echo "FAIL the uninterrupted run failed"; exit 1; }
if [[ $said == "gembem: 110 steps done in "* ]]; then echo "ok   uninterrupted: $said"
else echo "FAIL uninterrupted: '$said'"; fail=1; fi
(GB_TEST_KILL_AT=300 "$gembem" run "$scene" -o run --quiet) 2>/dev/null
[ -f run/checkpoint.txt ] || { echo "FAIL the run killed at its 300th write left no checkpoint"; exit 1; }
said=$("$gembem" run --resume run) || { echo "FAIL the resume failed"; exit 1; }
after=$(sed -n 's/.*after_step: \([0-9]*\),.*/\1/p' run/run_info.yaml)
if [ -n "$after" ] && [ "$after" -gt 0 ] &&
   [[ $said == "gembem: $((110 - after)) steps done in "*", resumed after step $after of 110; results in run" ]]; then
  echo "ok   resumed after step $after: $said"
else echo "FAIL resumed after step '$after' (run_info.yaml): '$said'"; fail=1; fi
exit $fail
