#!/usr/bin/env bash
# Benchmark of the solvers on packings that gembem did not make (a benchmark, not a test).
# For each N: the packing of tools/solver_packing.sh (gb_packgen --method push, porosity 0.18,
# overlaps <= 0.015 r_min, seed 1; cached in runs/bench_solver/nN), then with gembem: a
# frictionless relaxation, a friction relaxation (25 deg), and 1 % of oedometric compression in 20
# steps from the friction relaxation's state (from a relaxation by the reference iteration
# instead if the friction relaxation failed; the rows say so). Prints the machine and one
# Markdown row per run; a run that does not converge is a row, not a failure: the exit status is
# non-zero only for a usage error.
#
#   [SOLVER=global|reference] [LINEAR=cholmod|umfpack] [NEWTON=damped|line_search] [PERTURB=1e-9]
#   [MAX_ITERATIONS=...] [PATH_MAX_ITERATIONS=...] [REF_MAX_ITERATIONS=1000000]
#   [OPENBLAS_NUM_THREADS=1] [OMP_NUM_THREADS=1] [OPENBLAS_CORETYPE=...]
#   tools/bench_solver.sh [BUILD_DIR] [N ...]        (default: build, 1000 10000 100000)
#
# SOLVER, LINEAR, NEWTON: the solver of every run (default global, cholmod, damped; line_search
# needs umfpack). PERTURB=f: every centre
# moved by up to f times its radius (seeded) in a copy of the packing. MAX_ITERATIONS caps each
# relaxation (default 1000 for global, 1000000 for reference), PATH_MAX_ITERATIONS each load step
# of the path before its cut-backs (500; 1000000), REF_MAX_ITERATIONS the fallback reference
# relaxation (1000000). Each variant runs in runs/bench_solver/nN/SOLVER-LINEAR[-pF]/.
#
# Columns: iterations of the completed load steps (steps.csv; step 0, the initial state, left
# out), plus for a failed step its cap (steps.csv does not hold it: a relax step stops at the cap,
# a load step's cut-backs take more), mean and largest per completed step, steps cut
# back (substeps > 1), the largest fixing force at the end (of the failed step if one failed),
# wall seconds and peak resident memory of the gembem process (/usr/bin/time), and for the path
# the increments of the vertical and lateral stresses s1, s2 (steps.csv, compression positive,
# dyn/cm) from its start to 0.5 % and 1 % of vertical strain.
set -uo pipefail
source "$(dirname "$0")/lib.sh"
bench_args "$@"
usage() { echo "usage: [SOLVER=global|reference] [LINEAR=cholmod|umfpack] [NEWTON=damped|line_search] [PERTURB=f] tools/bench_solver.sh [BUILD_DIR] [N ...]" >&2; exit 2; }
export SOLVER=${SOLVER:-global} LINEAR=${LINEAR:-cholmod} NEWTON=${NEWTON:-damped}
case $SOLVER in global|reference) ;; *) echo "bench_solver.sh: SOLVER must be global or reference" >&2; usage;; esac
case $LINEAR in cholmod|umfpack) ;; *) echo "bench_solver.sh: LINEAR must be cholmod or umfpack" >&2; usage;; esac
case $NEWTON in damped|line_search) ;; *) echo "bench_solver.sh: NEWTON must be damped or line_search" >&2; usage;; esac
[ "$NEWTON" = damped ] || [ "$LINEAR" = umfpack ] || { echo "bench_solver.sh: NEWTON=line_search needs LINEAR=umfpack" >&2; usage; }
for n in $sizes; do
  [[ $n =~ ^[1-9][0-9]*$ ]] || { echo "bench_solver.sh: N must be a positive integer, got '$n'" >&2; usage; }
done
if [ -n "${PERTURB:-}" ]; then
  /usr/bin/python3 -c 'import sys; f = float(sys.argv[1]); sys.exit(not (0 <= f < 0.5))' "$PERTURB" 2>/dev/null ||
    { echo "bench_solver.sh: PERTURB must be a number in [0, 0.5), got '$PERTURB'" >&2; usage; }
fi
for exe in gembem gb_packgen; do
  [ -x "$build/$exe" ] || { echo "bench_solver.sh: $build/$exe not found: build first" >&2; usage; }
done
if [ "$SOLVER" = reference ]; then
  export MAX_ITERATIONS=${MAX_ITERATIONS:-1000000} PATH_MAX_ITERATIONS=${PATH_MAX_ITERATIONS:-1000000}
else
  export MAX_ITERATIONS=${MAX_ITERATIONS:-1000} PATH_MAX_ITERATIONS=${PATH_MAX_ITERATIONS:-500}
fi
export OPENBLAS_NUM_THREADS=${OPENBLAS_NUM_THREADS:-1} OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}
timer=/usr/bin/time
[ -x "$timer" ] || timer=
tag=$SOLVER; [ "$SOLVER" = global ] && tag=$SOLVER-$LINEAR
[ "$SOLVER" = global ] && [ "$NEWTON" = line_search ] && tag=$tag-line_search
[ -n "${PERTURB:-}" ] && tag=$tag-p$PERTURB
[ -n "${TAG:-}" ] && tag=$tag-$TAG # an experiment's own directory

echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc --all) cores, $(free -g | awk '/Mem:/ {print $2}') GiB; $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "threads: OPENBLAS_NUM_THREADS=$OPENBLAS_NUM_THREADS, OMP_NUM_THREADS=$OMP_NUM_THREADS; OPENBLAS_CORETYPE=${OPENBLAS_CORETYPE:-unset (detected)}; load average $(cut -d' ' -f1-3 /proc/loadavg)"
others=$(env | grep -E '^(OPENBLAS|GOTO|OMP|CHOLMOD)_' | grep -vE '^(OPENBLAS_NUM_THREADS|OMP_NUM_THREADS|OPENBLAS_CORETYPE)=' | sort | tr '\n' ' ')
[ -z "$others" ] || echo "also set: $others"
solver=$SOLVER; [ "$SOLVER" = global ] && solver="global, $LINEAR, newton $NEWTON"
echo "solver: $solver, accuracy 100 dyn; caps: relaxations $MAX_ITERATIONS, path steps $PATH_MAX_ITERATIONS iterations (cut-backs after); perturbation ${PERTURB:-none}"
[ -n "$timer" ] || echo "note: /usr/bin/time not found: no peak memory, seconds from bash"
echo
echo "| N | run | status | iterations | per step mean / max | steps cut back | final largest fixing force [dyn] | wall s | peak MB | ds1 at 0.5 % | ds2 at 0.5 % | ds1 at 1 % | ds2 at 1 % |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|"

# run NAME SCENE RUNDIR: gembem on the scene; leaves RUNDIR.log (stderr) and RUNDIR.time
# ("seconds kilobytes"); returns gembem's exit status.
run() {
  local scene=$2 dir=$3 code
  if [ -n "$timer" ]; then
    "$timer" -f "%e %M" -o "$dir.time" "$build/gembem" run "$scene" -o "$dir" --overwrite --quiet \
      > /dev/null 2> "$dir.log"
    code=$?
  else
    local t0=$SECONDS
    "$build/gembem" run "$scene" -o "$dir" --overwrite --quiet > /dev/null 2> "$dir.log"
    code=$?
    echo "$((SECONDS - t0)) -" > "$dir.time"
  fi
  return $code
}

# row N LABEL RUNDIR CODE [path]: one table row from the run's steps.csv, log and timing.
row() {
  local n=$1 label=$2 dir=$3 code=$4 is_path=${5:-} status force="" cap=""
  local secs mb
  read -r secs mb < <(grep -v 'status' "$dir.time" | tail -1)
  [ "$mb" = - ] || mb=$(awk -v k="$mb" 'BEGIN { printf "%.0f", k / 1024 }')
  if [ "$code" = 0 ]; then
    status=converged
  else
    local step
    step=$(sed -n "s/.*step \([0-9]*\) (stage.*did not converge.*/\1/p" "$dir.log" | head -1)
    if [ -n "$step" ]; then
      status="exit $code: step $step not converged"
      force=$(sed -n 's/.*largest fixing force \([0-9.eE+-]*\),.*/\1/p' "$dir.log" | head -1)
      cap=$(sed -n 's/.*did not converge in \([0-9]*\) iterations.*/\1/p' "$dir.log" | head -1)
    else # another failure: gembem's message; the force at the failure is not known
      status="exit $code: $(grep -m1 . "$dir.log" | sed 's/^gembem: //' | cut -c1-160 | tr '|' '/')"
      force=-
    fi
  fi
  if [ ! -s "$dir/steps.csv" ]; then
    echo "| $n | $label | $status | | | | | $secs | $mb | | | | |"
    return
  fi
  awk -F, -v n="$n" -v label="$label" -v status="$status" -v force="$force" -v secs="$secs" \
      -v mb="$mb" -v is_path="$is_path" -v cap="$cap" '
    NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next }
    { step = $c["step"]; s1[step] = $c["s1"]; s2[step] = $c["s2"]; last = $c["max_fixing_force"] }
    step > 0 { its = $c["iterations"]; tot += its; m++; if (its > mx) mx = its; if ($c["substeps"] > 1) cut++ }
    function inc(s, k) { return (k in s) ? sprintf("%.4g", s[k] - s[0]) : "-" }
    END {
      if (force == "") force = last
      per = m ? sprintf("%.1f / %d", tot / m, mx) : "-"
      d = is_path ? sprintf("%s | %s | %s | %s", inc(s1, 10), inc(s2, 10), inc(s1, 20), inc(s2, 20)) : " | | | "
      its = status == "converged" ? tot + 0 : cap != "" ? sprintf("%d + >= %d in the failed step", tot, cap) \
                                                        : sprintf("%d + those of the failed step", tot)
      if (force != "-") force = sprintf("%.4g", force)
      printf "| %s | %s | %s | %s | %s | %d | %s | %s | %s | %s |\n", n, label, status, its, per, cut, force, secs, mb, d
    }' "$dir/steps.csv"
}

for n in $sizes; do
  d=$root/runs/bench_solver/n$n
  v=$d/$tag
  mkdir -p "$d"
  if [ -s "$d/packing.csv" ] && [ -s "$d/packing.box.yaml" ]; then
    echo "n = $n: cached packing $d/packing.csv: $(sed -n 's/.*then \([0-9]*\) push-apart sweeps.*/\1 sweeps/p' "$d/packing.box.yaml")" >&2
  else
    t0=$(date +%s.%N)
    if ! KEEP=1 "$root/tools/solver_packing.sh" "$build" "$d" "$n" 1 > /dev/null; then
      echo "| $n | packing | gb_packgen failed (see above) | | | | | | | | | | |"
      continue
    fi
    echo "n = $n: packing made in $(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }') s" >&2
  fi
  PACKING=$d/packing.csv "$root/tools/solver_packing.sh" "$build" "$v" "$n" 1 > /dev/null || {
    echo "| $n | scenes | tools/solver_packing.sh failed | | | | | | | | | | |"; continue; }

  run relax_frictionless "$v/relax_frictionless.yaml" "$v/relax_frictionless"
  row "$n" "relax frictionless" "$v/relax_frictionless" $?
  run relax_friction "$v/relax_friction.yaml" "$v/relax_friction"
  code=$?
  row "$n" "relax friction" "$v/relax_friction" $code
  from="friction relaxation"
  if [ $code != 0 ]; then
    # The path needs an equilibrium to start from: the reference iteration's, and the row says so.
    run relax_friction_reference "$v/relax_friction_reference.yaml" "$v/relax_friction_reference"
    code=$?
    row "$n" "relax friction by the reference iteration (start of the path)" "$v/relax_friction_reference" $code
    from="reference relaxation"
    PACKING=$d/packing.csv "$root/tools/solver_packing.sh" "$build" "$v" "$n" 1 \
      "$v/relax_friction_reference" > /dev/null
  fi
  if [ $code != 0 ]; then
    echo "| $n | path | not run: the $from failed too | | | | | | | | | | |"
    continue
  fi
  run path "$v/path.yaml" "$v/path"
  row "$n" "path (from the $from)" "$v/path" $? path
done
exit 0
