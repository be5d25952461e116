#!/usr/bin/env bash
# The scaling table (not a test): one load step (+5 % of the isotropic stress, stress control, a =
# 1e-6 kn r_mean) with each solver (build/bench_jammed; the reference iteration up to 1e5 discs) on
# packings of 1e3, 1e4, 1e5 and 1e6 discs:
# - PACKINGS=random (the default): random packings of `gembem pack` (tools/bench_pack.sh with
#   FRICTION_DEG=10: grown to 1e-4 kn at 10 degrees, porosity about 0.18; cached in
#   runs/bench_pack/nN_f10, made on PACK_THREADS=2 threads if missing: 35 minutes at 1e6), the load
#   step's scene starting from the packing's state (its tangential forces included), in
#   runs/scaling/f10_nN;
# - PACKINGS=jammed (the second case, the table of sessions 7-11): frictionless packings grown to
#   solid fraction 0.85 (tools/jammed_packing.sh, runs/bench_gem/nN) and at 1e6 the 1e4 one
#   mirrored into 10 x 10 copies (tools/mirrored_packing.sh, runs/scaling/m10000x10).
# Prints a Markdown table: seconds, peak resident memory and where the time went, then the fitted
# exponent b of seconds ~ N^b per solver (least squares on log-log); bench_jammed's stderr is kept
# beside the scene (bench_jammed_SOLVER.log; BENCH_PROGRESS=1: a line per iteration). One BLAS
# thread unless the caller sets OPENBLAS_NUM_THREADS / OMP_NUM_THREADS.
#   [PACKINGS=random|jammed] [SOLVERS="line_search cholmod reference"] tools/bench_scaling.sh [BUILD_DIR] [N ...]
#   (N: 1000 10000 100000 1000000)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build_arg=${1:-build} # as the tools take it: relative to the repository
build=$root/$build_arg; shift || true
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
  if [ "${PACKINGS:-random}" = random ]; then
    # a random packing of N discs from `gembem pack` at 10 degrees (tools/bench_pack.sh, cached), at
    # its own accuracy: the load step's scene starts from its state, tangential forces included
    p=$root/runs/bench_pack/n${n}_f10
    [ -s "$p/out/state.yaml" ] || FRICTION_DEG=10 THREADS=${PACK_THREADS:-2} "$root/tools/bench_pack.sh" "$build_arg" "$n" > /dev/null
    d=$root/runs/scaling/f10_n$n
    mkdir -p "$d"
    { sed -n '/^gembem:/,/^materials:/p; /^  grain_/p' "$p/scene.yaml"
      printf 'initial_state: %s\nsolver: {accuracy: 100}\n' "$p/out/state.yaml"
      printf 'loading:  # not used: bench_jammed drives the walls itself\n  - isotropic: {stress: 1.0e4, steps: 1}\n'
    } > "$d/scene.yaml"
  elif [ "${PACKINGS:-random}" != jammed ]; then
    echo "bench_scaling.sh: PACKINGS is random or jammed, not $PACKINGS" >&2; exit 2
  elif [ "$n" = 1000000 ]; then
    d=$root/runs/scaling/m10000x10
    KEEP=1 "$root/tools/mirrored_packing.sh" "$build" "$d" 10000 1 10 10
  else
    d=$root/runs/bench_gem/n$n
    KEEP=1 "$root/tools/jammed_packing.sh" "$build" "$d" "$n" 1 10
  fi
  for s in ${SOLVERS:-line_search cholmod reference}; do
    [ "$s" = reference ] && [ "$n" -gt 100000 ] && continue
    err=$(mktemp)
    row=$("$build/bench_jammed" "$d/scene.yaml" 1 "$s" 100 target 2> "$err") || true
    # | solver | N | contacts | prep | s_r | a | its | s/it | ns | seconds | MB |
    IFS='|' read -r _ solver nn contacts _ _ _ its _ _ secs mb _ <<< "$row"
    split=$(grep 'load steps:' "$err" | head -1)
    mv "$err" "$d/bench_jammed_$s.log" # kept beside the packing (with BENCH_PROGRESS=1, a line per iteration)
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
