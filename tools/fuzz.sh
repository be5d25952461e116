#!/usr/bin/env bash
# Fuzzes the readers with libFuzzer: builds fuzz/'s targets with clang, ASan and UBSan
# in build-fuzz/, then runs each in turn (one core) for SECONDS (default 60), starting from its
# seed corpus fuzz/corpus/<target> and what earlier runs kept in build-fuzz/corpus/<target>.
#   tools/fuzz.sh [seconds] [target ...]     targets: scene grains contacts state bem mesh (the default)
#   RUNS=1000000 tools/fuzz.sh 1800          each target until 1e6 executions or 30 minutes
# Prints per target the executions, the time and the findings (a crash, a sanitizer report, a leak,
# a timeout of FUZZ_TIMEOUT s (default 30) or more than 2 GB), which libFuzzer writes to
# build-fuzz/findings/<target>/ (on a machine busy with other work an input can pass 30 s by waiting
# for the CPU alone: a larger FUZZ_TIMEOUT there, and every timeout replayed alone before it counts);
# exits 1 if there is any. libFuzzer stops a target at its first finding; once fixed, the input
# goes to fuzz/regress/<target>/ (ctest replays it). Leaks: libFuzzer checks after every input
# whose mallocs and frees differ, a full LeakSanitizer scan that gmsh (which keeps memory from one
# load to the next) would trigger on every input that meshes a host; for the targets that mesh,
# LeakSanitizer checks once at exit instead (its report names where the leaked block was allocated).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(scene grains contacts state bem mesh)
tools/setup.sh
if ! command -v clang >/dev/null; then # Debian's clang brings libFuzzer and the sanitizers
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq clang
fi
dir=build-fuzz
CC=clang cmake -S . -B $dir -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGB_FUZZ=ON >/dev/null
cmake --build $dir -j "$(nproc)" --target "${targets[@]/#/fuzz_}" >/dev/null
found=0
printf '%-9s %12s %8s %8s  %s\n' target executions seconds exec/s findings
for t in "${targets[@]}"; do
  rm -rf $dir/findings/$t # this run's findings only
  mkdir -p $dir/corpus/$t $dir/findings/$t $dir/logs
  start=$(date +%s)
  # the readers print nothing; libFuzzer's progress goes to the log
  leaks=0; [ "$t" = grains ] && leaks=1
  slow=${FUZZ_TIMEOUT:-30} # an input this slow is a timeout: reported once, as one
  $dir/fuzz/fuzz_$t $dir/corpus/$t fuzz/corpus/$t -max_total_time="$seconds" -runs="${RUNS:--1}" \
    -timeout="$slow" -report_slow_units="$slow" -rss_limit_mb=2048 -detect_leaks=$leaks -print_final_stats=1 \
    -artifact_prefix=$dir/findings/$t/ \
    >$dir/logs/$t.log 2>&1 || true
  secs=$(($(date +%s) - start))
  runs=$(awk '/stat::number_of_executed_units/ {print $2; exit}' $dir/logs/$t.log) # printed twice after a leak report
  n=$(ls $dir/findings/$t | wc -l)
  grep -q "ERROR: LeakSanitizer" $dir/logs/$t.log && n=$((n + 1)) # at exit: no input to keep
  found=$((found + n))
  printf '%-9s %12s %8s %8s  %s\n' "$t" "${runs:-?}" "$secs" "$(( ${runs:-0} / (secs > 0 ? secs : 1) ))" \
    "$([ "$n" -eq 0 ] && echo none || echo "$n in $dir/findings/$t (log: $dir/logs/$t.log)")"
done
[ $found -eq 0 ]
