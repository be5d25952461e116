#!/usr/bin/env bash
# The scaling table (not a test): one load step (+5 % of the isotropic stress, stress control, a =
# 1e-6 kn r_mean) on jammed packings of 1e3, 1e4, 1e5 discs (tools/jammed_packing.sh, cached in
# runs/bench_gem/nN) and of 1e6 discs (tools/mirrored_packing.sh: the 1e4 packing jammed between
# walls of 2 kn and mirrored into 10 x 10 copies, cached in runs/scaling/m10000x10), with each
# solver (build/bench_jammed; the reference iteration up to 1e5 discs). Prints a Markdown table:
# seconds, peak resident memory and where the time went, then the fitted exponent b of
# seconds ~ N^b per solver (least squares on log-log). One BLAS thread unless the caller sets
# OPENBLAS_NUM_THREADS / OMP_NUM_THREADS.
#   [SOLVERS="reference cholmod"] tools/bench_scaling.sh [BUILD_DIR] [N ...]   (N: 1000 10000 100000 1000000)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/${1:-build}; shift || true
sizes=${*:-1000 10000 100000 1000000}
export OPENBLAS_NUM_THREADS=${OPENBLAS_NUM_THREADS:-1} OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}
rows=$(mktemp)
trap 'rm -f "$rows"' EXIT
echo "machine: $(nproc --all) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(free -g | awk '/Mem:/ {print $2}') GiB; $(date -u +%Y-%m-%d)"
echo "threads: OPENBLAS_NUM_THREADS=$OPENBLAS_NUM_THREADS; load average $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| solver | N | contacts | iterations | seconds | peak memory [MB] | contact detection s | assembly s | analyses (s) | factorisations (s) | solves s | the rest s |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
for n in $sizes; do
  if [ "$n" = 1000000 ]; then
    d=$root/runs/scaling/m10000x10
    KEEP=1 "$root/tools/mirrored_packing.sh" "$build" "$d" 10000 1 10 10
  else
    d=$root/runs/bench_gem/n$n
    KEEP=1 "$root/tools/jammed_packing.sh" "$build" "$d" "$n" 1 10
  fi
  for s in ${SOLVERS:-reference cholmod}; do
    [ "$s" = reference ] && [ "$n" -gt 100000 ] && continue
    err=$(mktemp)
    row=$("$build/bench_jammed" "$d/scene.yaml" 1 "$s" 100 target 2> "$err") || true
    # | solver | N | contacts | prep | s_r | a | its | s/it | ns | seconds | MB |
    IFS='|' read -r _ solver nn contacts _ _ _ its _ _ secs mb _ <<< "$row"
    split=$(grep 'load steps:' "$err" | head -1)
    rm -f "$err"
    num() { sed -n "s/.*$1 \([0-9.]*\) s.*/\1/p" <<< "$split"; }
    count() { sed -n "s/.* \([0-9]*\) $1 \([0-9.]*\) s.*/\2 (\1)/p" <<< "$split"; }
    rest=$(sed -n 's/.*the rest ([^)]*) \([0-9.]*\) s.*/\1/p' <<< "$split")
    printf "|%s|%s|%s|%s|%s|%s| %s | %s | %s | %s | %s | %s |\n" "$solver" "$nn" "$contacts" "$its" "$secs" "$mb" \
      "$(num 'contact detection')" "$(num assembly)" "$(count analyses)" "$(count factorisations)" "$(num solves)" "$rest"
    echo "$(tr -d ' ' <<< "$solver") $(tr -d ' ' <<< "$nn") $(tr -d ' ' <<< "$secs")" >> "$rows"
  done
done
echo
awk '{ n[$1]++; x = log($2); y = log($3); sx[$1] += x; sy[$1] += y; sxx[$1] += x * x; sxy[$1] += x * y }
     END { for (s in n) if (n[s] > 1) printf "%s: seconds ~ N^%.2f over %d sizes\n", s,
             (n[s] * sxy[s] - sx[s] * sy[s]) / (n[s] * sxx[s] - sx[s] * sx[s]), n[s] }' "$rows"
