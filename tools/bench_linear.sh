#!/usr/bin/env bash
# The linear solvers' costs for docs/scaling.md (a benchmark, not a test): one global-solver
# iteration (build/bench_linear: a load step's first, the walls 5 % above the packing's stress)
# on each packing directory's scene.yaml (tools/jammed_packing.sh, tools/mirrored_packing.sh),
# solved by CHOLMOD, by PETSc with MUMPS's Cholesky on 1 and 2 MPI ranks and by CG + GAMG on 2
# ranks. Prints a Markdown table: unknowns, matrix entries, factor entries and flops (CHOLMOD's
# analysis; MUMPS's INFOG(29) and RINFOG(3) from -ksp_view), factorisations, KSP iterations,
# seconds (assembly, analysis, factorisation or set-up, solve) and every rank's peak resident
# memory (/usr/bin/time; rank 0 first). One BLAS thread per rank unless OPENBLAS_NUM_THREADS is set.
#   [CONFIGS="cholmod:1 mumps:1 mumps:2 gamg:2"] tools/bench_linear.sh BUILD_DIR PACKING_DIR ...
set -euo pipefail
build=$(cd "$1" && pwd); shift
export OPENBLAS_NUM_THREADS=${OPENBLAS_NUM_THREADS:-1} OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
echo "machine: $(nproc --all) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(free -g | awk '/Mem:/ {print $2}') GiB; $(date -u +%Y-%m-%dT%H:%MZ)"
echo "threads: OPENBLAS_NUM_THREADS=$OPENBLAS_NUM_THREADS; load average $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| solver | ranks | grains | unknowns | entries | factor entries | factor flops | factorisations | KSP its | assembly s | analysis s | factorisation s | solve s | peak MB per rank |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
log=$(mktemp) out=$(mktemp)
trap 'rm -f "$log" "$out"' EXIT
for d in "$@"; do
  for conf in ${CONFIGS:-cholmod:1 mumps:1 mumps:2 gamg:2}; do
    s=${conf%:*} p=${conf#*:}
    scene=$d/scene.yaml
    if [ "$s" = gamg ]; then
      sed 's/^solver: {/solver: {linear: petsc, petsc: {ksp: cg, pc: gamg}, /' "$d/scene.yaml" > "$d/bench_gamg.yaml"
      scene=$d/bench_gamg.yaml
    fi
    solver=$([ "$s" = cholmod ] && echo cholmod || echo petsc)
    launch=(); [ "$s" = cholmod ] || launch=(mpirun --oversubscribe -np "$p")
    view=""; [ "$s" = mumps ] && view="-ksp_view"
    # every rank's peak, labelled with its rank (Open MPI's OMPI_COMM_WORLD_RANK)
    row=$(PETSC_OPTIONS="$view" "${launch[@]}" bash -c \
          'exec /usr/bin/time -f "peak-kB ${OMPI_COMM_WORLD_RANK:-0} %M" "$@"' _ "$build/bench_linear" "$scene" "$solver" \
          > "$out" 2> "$log"; grep '^|' "$out" || true)
    mem=$(sed -n 's/^peak-kB //p' "$log" | sort -n | awk '{ if (NR > 1) printf ", "; printf "%.0f", $2 / 1024 }')
    if [ "$s" = mumps ]; then # MUMPS's own counts, from the last -ksp_view, into the factor columns
      fe=$(grep 'INFOG(29)' "$out" | tail -1 | sed 's/.*: //') ff=$(grep 'RINFOG(3)' "$out" | tail -1 | sed 's/.*: //')
      row=$(awk -F'|' -v fe="$fe" -v ff="$ff" -v s="petsc mumps" 'BEGIN { OFS = "|" } { $2 = " " s " "; $7 = " " fe " "; $8 = " " ff " "; print }' <<< "$row")
    elif [ "$s" = gamg ]; then
      row=$(awk -F'|' 'BEGIN { OFS = "|" } { $2 = " petsc cg+gamg "; print }' <<< "$row")
    fi
    echo "${row% | *} | $mem |"
  done
done
