#!/usr/bin/env bash
# Peer benchmark against LAMMPS (a benchmark, not a test): for each N, the
# packing of tools/bench_solver.sh (tools/solver_packing.sh: gb_packgen --method push, porosity
# 0.18, overlaps <= 0.015 r_min, seed 1; cached in runs/bench_peer/nN), relaxed with 25 deg
# between discs, walls fixed and frictionless, kn = 1e8, kt = 7e7 dyn/cm, to every disc's largest
# fixing force <= 100 dyn:
#   - by LAMMPS (Debian's `lammps`: explicit DEM, one process, serial; input written by
#     tools/lammps_peer.py, which documents the model line by line);
#   - by gembem: the global solver with `newton: line_search` + UMFPACK, the damped global solver
#     with CHOLMOD, and (N <= REF_MAX_N, default 10000) the reference iteration.
# Every final state, LAMMPS's too, is checked by tools/check_equilibrium.py: it recomputes every
# disc's force and moment from the positions and the stored tangential forces (LAMMPS's, from
# `compute pair/local p1 p2` with the velocities zeroed: no damping forces). With `path` in RUNS,
# also the users' main workload: a 1 % oedometric loading path by both codes from one equilibrium,
# LAMMPS at several loading rates, the stress paths compared (path_rows below). With `shear` in
# RUNS, a path where the grains rearrange: the constant-volume biaxial shear to 5 % by both codes,
# each from its own relaxation, gembem in several load-step counts, LAMMPS at several rates and a
# repeat with other start velocities, compared as statistics (shear_rows below,
# tools/shear_stats.py). Prints the machine and one Markdown row per run; a run that fails is a
# row: the exit status is non-zero only for a usage error or a set-up failure (LAMMPS not
# installable, the contact-law check failing).
#
#   [LAMMPS_DT=0.2] [LAMMPS_ZETA=0.5] [LAMMPS_TDAMP=1] [LAMMPS_VISCOUS=0.01]
#   [LAMMPS_MAX_STEPS=20000000] [MAX_ITERATIONS=1000] [REF_MAX_ITERATIONS=1000000]
#   [REF_MAX_N=10000] [RUNS="lammps line_search damped reference path shear"] [SWEEP=1]
#   [LAMMPS_PATH_STEPS="3120 6240 12480 24960 49920"] (path: the loading's time steps, multiples of 20)
#   [PATH_STRESS=1e5] (path: the start's isotropic stress, dyn/cm; 0: the relaxed packing)
#   [PATH_START=DIR] (path: start from this state directory instead, e.g. a `gembem pack` packing
#   pressed to a stress; N must be its grains' count)
#   [SHEAR_STEPS="25 50 100"] (shear: gembem's load-step counts) [SHEAR_STRAIN=0.05] (e1 at the end)
#   [LAMMPS_SHEAR_STEPS="100000 200000 400000"] (shear: LAMMPS's time steps for the whole strain,
#   multiples of 20) [LAMMPS_SHEAR_REPEAT="100000:2"] (the repeats, STEPS:SEED, empty for none;
#   the rates use seed 1)
#   [LAMMPS_SHEAR_V0=0.01] (the start velocities' standard deviation over the top wall's speed)
#   [SHEAR_SOLVER="method: global, linear: umfpack, newton: line_search, max_iterations: 500"]
#   [SHEAR_SOLVER_EXTRA=""] (more keys of gembem's solver map, e.g. "history: true"; a key of
#   SHEAR_SOLVER repeated is refused by gembem: change SHEAR_SOLVER instead; threads and accuracy
#   are always THREADS and a) [SHEAR_START=own|pressed] (own: each code's relaxation; pressed:
#   both from the path's start) [SHEAR_REUSE=1] (keep the starts and LAMMPS's shear runs of an
#   earlier invocation whose inputs are the same: another gembem solver on the same path)
#   [RANKS=1] (LAMMPS on RANKS MPI processes: mpirun, Debian's openmpi-bin) [THREADS=1] (gembem's
#   solver.threads) [KN_SCALE=1] (kn, kt and the static criterion times KN_SCALE: the same
#   packing with stiffer springs, the cost in kn)
#   tools/bench_peer.sh [BUILD_DIR] [N ...]        (default: build, 1000 10000 100000)
#
# Set-up (this script's own; tools/setup.sh and the tests do not need LAMMPS): `lmp` and
# /usr/bin/time are installed with apt-get (Debian packages `lammps`, `time`; sudo if not root)
# when absent; then tools/lammps_peer.py lawcheck compares LAMMPS's gran/hooke/history on two
# discs (pressed, slid, spun, slid beyond the cap) with gembem's law (docs/method.md K 3, 6, 13).
#
# LAMMPS's parameters (tools/lammps_peer.py input): time step dt = LAMMPS_DT sqrt(m_min / kn)
# (masses rho pi r^2, rho = 2.65 g/cm^3: they only set the dynamics); normal contact damping
# LAMMPS_ZETA of critical for two of the smallest discs, tangential contact damping (dampflag
# LAMMPS_TDAMP) gammat = gamman / 2; global drag (fix viscous, proportional to each disc's mass)
# -LAMMPS_VISCOUS sqrt(kn / m_min) m v. The run stops when a `fix halt` heuristic (every disc's
# force as integrated, drag added back, below 100 dyn, checked every 50 steps) fires; then the
# velocities and spins are zeroed, the static forces evaluated (`run 0`), and the run goes on if
# a disc's is still above 100 dyn (the zeroing counts as part of LAMMPS's method; it helps).
#
# The damping sweep (SWEEP=1 tools/bench_peer.sh build 1000 runs it: LAMMPS only, the grid
# SWEEP_DT x SWEEP_ZETA x SWEEP_TDAMP x SWEEP_VISCOUS, one row each, time steps to the static
# criterion and seconds): 2026-11-24 at N = 1 000, steps (one run each; the relaxation path is
# chaotic, so neighbouring settings scatter by about 2x):
#   dt 0.2, tangential damping on; viscous (columns) 0 / 0.003 / 0.01 / 0.02 / 0.05, zeta_n (rows):
#     zeta_n 0    : >400 000 (7 644 dyn left) / 191 300 / 66 000 / 41 950 / 13 550
#     zeta_n 0.1  :  19 750 /  8 600 /  7 600 /  8 500 / 24 150
#     zeta_n 0.3  :   9 800 /  7 050 /  5 350 /  8 050 /  8 850
#     zeta_n 0.5  :   9 900 /  6 100 /  4 050 /  7 100 / 13 850
#     zeta_n 1.0  :  12 500 / 11 800 / 20 950 / 25 100 / 28 000
#   around the best (zeta_n 0.5, viscous 0.01): dt 0.1: 7 750 steps; dt 0.3: diverges (48 439 dyn
#   after 400 000 steps: the contact damping shortens the stable step), dt 0.3 with zeta_n 0.3:
#   4 150; tangential damping off: 4 500 (zeta_n 0.5), 6 200 (0.3).
# Chosen (the defaults): dt 0.2 (the largest step of the range 0.1-0.2 that is stable for every
# damping of the sweep), zeta_n 0.5, tangential damping on, viscous 0.01: 4 050 steps. The best
# global drag should fall as the packing grows (its slowest mode's frequency falls as 1 / width):
# the defaults are tuned at 1e3. At 1e4 (zeta_n 0.5): viscous 0.003 10 900 steps, 0.01 5 550, 0.05
# 102 200; but the fast settings unjam the 1e4 packing (398 contacts and 1.4 dyn/cm left at 0.01,
# against gembem's 15 000 and 1.5-3.7e3 dyn/cm): see docs/benchmarks.md, "Against LAMMPS".
#
# Columns: N; code and solver; status (gembem's exit status, or LAMMPS's static check, then the
# independent check); gembem's iterations or LAMMPS's time steps; wall seconds and peak resident
# memory of the process (/usr/bin/time, -f "%e %M"; LAMMPS's include its MPI start-up, about
# 30 MB); the largest fixing force by tools/check_equilibrium.py; LAMMPS's seconds over this row's
# (only for runs whose final state passed the check); the final state's grain-grain contacts and
# wall stresses s1 (vertical), s2 (horizontal), by the checker: the codes reach different
# equilibria (friction makes the end state depend on the path), and these show how different.
set -uo pipefail
source "$(dirname "$0")/lib.sh"
bench_args "$@"
usage() { echo "usage: [LAMMPS_DT=..] [LAMMPS_ZETA=..] [LAMMPS_TDAMP=0|1] [LAMMPS_VISCOUS=..] [RUNS=\"lammps line_search damped reference path shear\"] [SWEEP=1] tools/bench_peer.sh [BUILD_DIR] [N ...] (more in the header)" >&2; exit 2; }
for n in $sizes; do
  [[ $n =~ ^[1-9][0-9]*$ ]] || { echo "bench_peer.sh: N must be a positive integer, got '$n'" >&2; usage; }
done
for exe in gembem gb_packgen; do
  [ -x "$build/$exe" ] || { echo "bench_peer.sh: $build/$exe not found: build first" >&2; usage; }
done
LAMMPS_DT=${LAMMPS_DT:-0.2} LAMMPS_ZETA=${LAMMPS_ZETA:-0.5} LAMMPS_TDAMP=${LAMMPS_TDAMP:-1}
LAMMPS_VISCOUS=${LAMMPS_VISCOUS:-0.01} LAMMPS_MAX_STEPS=${LAMMPS_MAX_STEPS:-20000000}
REF_MAX_N=${REF_MAX_N:-10000} RUNS=${RUNS:-lammps line_search damped reference}
LAMMPS_PATH_STEPS=${LAMMPS_PATH_STEPS:-3120 6240 12480 24960 49920} PATH_STRESS=${PATH_STRESS:-1e5}
psfx=""; [ "$PATH_STRESS" = 0 ] || psfx=_p$PATH_STRESS # the path runs' directory
PATH_START=${PATH_START:-} # path: a state directory to start from instead (its grains' count is N)
[ -z "$PATH_START" ] || { PATH_START=$(cd "$PATH_START" && pwd); psfx=_start_$(basename "$(dirname "$PATH_START")"); }
RANKS=${RANKS:-1}
SHEAR_START=${SHEAR_START:-own} SHEAR_STRAIN=${SHEAR_STRAIN:-0.05} SHEAR_STEPS=${SHEAR_STEPS:-25 50 100}
SHEAR_SOLVER_DEFAULT="method: global, linear: umfpack, newton: line_search, max_iterations: 500"
SHEAR_SOLVER=${SHEAR_SOLVER:-$SHEAR_SOLVER_DEFAULT} SHEAR_SOLVER_EXTRA=${SHEAR_SOLVER_EXTRA:-}
LAMMPS_SHEAR_STEPS=${LAMMPS_SHEAR_STEPS:-100000 200000 400000} LAMMPS_SHEAR_V0=${LAMMPS_SHEAR_V0:-0.01}
LAMMPS_SHEAR_REPEAT=${LAMMPS_SHEAR_REPEAT-${LAMMPS_SHEAR_STEPS%% *}:2} SHEAR_REUSE=${SHEAR_REUSE:-0}
case $SHEAR_START in own|pressed) ;; *) echo "bench_peer.sh: SHEAR_START must be own or pressed" >&2; usage;; esac
for S in $SHEAR_STEPS $LAMMPS_SHEAR_STEPS ${LAMMPS_SHEAR_REPEAT//:/ }; do
  [[ $S =~ ^[1-9][0-9]*$ ]] || { echo "bench_peer.sh: SHEAR_STEPS, LAMMPS_SHEAR_STEPS and LAMMPS_SHEAR_REPEAT (STEPS:SEED) take positive integers, got '$S'" >&2; usage; }
done
awk -v e="$SHEAR_STRAIN" 'BEGIN { k = e / 0.0025; exit !(k >= 0.5 && k < 200 && (k - int(k + 0.5)) ^ 2 < 1e-12) }' ||
  { echo "bench_peer.sh: SHEAR_STRAIN must be a multiple of 0.0025 (the curves' points) below 0.5, got '$SHEAR_STRAIN'" >&2; usage; }
export KN_SCALE=${KN_SCALE:-1} # read by tools/solver_packing.sh
sfx=""; [ "$KN_SCALE" = 1 ] || sfx=_kn$KN_SCALE # the runs' directories
read -r kn kt acc < <(awk -v s="$KN_SCALE" 'BEGIN { printf "%.6g %.6g %.6g\n", 1.0e8 * s, 7.0e7 * s, 100 * s }')
export THREADS=${THREADS:-1} # read by tools/solver_packing.sh
export MAX_ITERATIONS=${MAX_ITERATIONS:-1000} REF_MAX_ITERATIONS=${REF_MAX_ITERATIONS:-1000000}
export OPENBLAS_NUM_THREADS=${OPENBLAS_NUM_THREADS:-1} OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}
py=/usr/bin/python3

# Set-up: LAMMPS and GNU time from Debian, if absent.
need=()
command -v lmp > /dev/null || need+=(lammps)
[ -x /usr/bin/time ] || need+=(time)
[ "$RANKS" = 1 ] || command -v mpirun > /dev/null || need+=(openmpi-bin)
if [ ${#need[@]} -gt 0 ]; then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "bench_peer.sh: installing ${need[*]} (apt-get)" >&2
  { $sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${need[@]}"; } >&2 ||
    { echo "bench_peer.sh: could not install ${need[*]}" >&2; exit 1; }
fi
timer=/usr/bin/time
top=$root/runs/bench_peer
mkdir -p "$top"
lmp_version=$(lmp -h 2>/dev/null | sed -n 's/^Large-scale Atomic\/Molecular Massively Parallel Simulator - \(.*\)$/\1/p' | head -1)

# The contact law, once: LAMMPS's gran/hooke/history against gembem's on two discs.
if ! law=$($py "$root/tools/lammps_peer.py" lawcheck "$top/lawcheck" 2>&1); then
  echo "$law" >&2
  echo "bench_peer.sh: LAMMPS's contact law does not match gembem's (see above): no benchmark" >&2
  exit 1
fi

echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc --all) cores, $(free -g | awk '/Mem:/ {print $2}') GiB; $(date -u '+%Y-%m-%d %H:%M UTC'); load average $(cut -d' ' -f1-3 /proc/loadavg)"
lmp_cmd=(lmp) lmp_label="LAMMPS gran/hooke/history (explicit DEM)" gb_label=""
if [ "$RANKS" != 1 ]; then # Open MPI refuses root unless told
  lmp_cmd=(mpirun -np "$RANKS" $([ "$(id -u)" -ne 0 ] || echo --allow-run-as-root) lmp)
  lmp_label="$lmp_label, $RANKS MPI ranks"
fi
[ "$THREADS" = 1 ] || gb_label=", solver.threads $THREADS"
echo "threads: OPENBLAS_NUM_THREADS=$OPENBLAS_NUM_THREADS, OMP_NUM_THREADS=$OMP_NUM_THREADS; gembem solver.threads $THREADS; LAMMPS ${lmp_cmd[*]}"
echo "gembem $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo '?'); LAMMPS ${lmp_version:-?} (Debian $(dpkg-query -W -f='${Version}' lammps 2>/dev/null || echo '?'))"
echo "LAMMPS: dt $LAMMPS_DT sqrt(m_min/kn), zeta_n $LAMMPS_ZETA, tangential damping $LAMMPS_TDAMP, viscous $LAMMPS_VISCOUS sqrt(kn/m_min) m; contact law check: $(echo "$law" | tail -1)"
echo "problem: 25 deg between discs, frictionless fixed walls, kn $kn, kt $kt dyn/cm; static criterion: every disc's largest fixing force <= $acc dyn (tools/check_equilibrium.py)"
echo

# timed OUT_PREFIX DIR CMD...: CMD in DIR under /usr/bin/time; OUT_PREFIX.time gets "wall-s KB
# user-s system-s", OUT_PREFIX.log stderr; returns CMD's exit status.
timed() {
  local out=$1 dir=$2; shift 2
  (cd "$dir" && "$timer" -f "%e %M %U %S" -o "$out.time" "$@" > "$out.out" 2> "$out.log")
}
# secs_mb OUT_PREFIX: "seconds megabytes" from the timing file
secs_mb() { grep -v status "$1.time" | tail -1 | awk '{ printf "%s %.0f", $1, $2 / 1024 }'; }
# cpu_secs OUT_PREFIX: the process's CPU seconds (user + system) from the timing file
cpu_secs() { grep -v status "$1.time" | tail -1 | awk '{ printf "%.2f", $3 + $4 }'; }
# check DIR: the independent checker, at the one static criterion of every row (100 dyn; a LAMMPS
# state has no steps.csv with a resolved accuracy); sets chk (passed / FAILED ...) and force
check() {
  local out
  out=$($py "$root/tools/check_equilibrium.py" "$1" --accuracy "$acc" 2>&1)
  local code=$?
  force=$(echo "$out" | sed -n 's/.*largest fixing force \([0-9.eE+-]*\) dyn.*/\1/p' | head -1)
  force=${force:--}
  contacts=$(echo "$out" | sed -n 's/^  state: \([0-9]*\) grain-grain contacts.*/\1/p')
  stress=$(echo "$out" | sed -n 's/.*wall stresses s1 \([0-9.eE+-]*\), s2 \([0-9.eE+-]*\).*/\1, \2/p')
  case $code in
    0) chk="check passed";;
    1) chk="check FAILED: $(echo "$out" | grep -m1 FAIL | sed 's/^ *FAIL //' | tr '|' '/' | cut -c1-100)";;
    *) chk="check not run: $(echo "$out" | tail -1 | tr '|' '/' | cut -c1-100)";;
  esac
}

# lammps_run N DIR DT ZETA TDAMP VISCOUS [GRAINS.csv BOX.yaml [ARGS...]]: writes the input (from
# the packing, or from GRAINS and BOX, with lammps_peer.py's further ARGS), runs lmp, converts and
# checks the final state; sets lmp_status, lmp_steps, lmp_secs, lmp_mb, lmp_force, lmp_ok.
lammps_run() {
  local n=$1 d=$2 code grains=${7:-$top/n$1/packing.csv} box=${8:-$top/n$1/packing.box.yaml}
  rm -rf "$d"; mkdir -p "$d"
  $py "$root/tools/lammps_peer.py" input "$grains" "$box" "$d" \
    --dt-factor "$3" --zeta-n "$4" --tangential-damping "$5" --viscous "$6" \
    --max-steps "$LAMMPS_MAX_STEPS" --kn-scale "$KN_SCALE" --accuracy "$acc" "${@:9}" > /dev/null
  timed "$d/lmp" "$d" "${lmp_cmd[@]}" -nocite -in in.relax -log log.lammps -screen none
  code=$?
  read -r lmp_secs lmp_mb < <(secs_mb "$d/lmp")
  lmp_ok=0 lmp_steps="" lmp_force=- lmp_contacts="" lmp_stress=""
  if [ $code != 0 ]; then
    lmp_status="exit $code: $(grep -m1 ERROR "$d/log.lammps" 2>/dev/null | tr '|' '/' | cut -c1-120)"
    return
  fi
  local last
  last=$(sed -n 's/^final: step \([0-9]*\) largest force \([0-9.eE+-]*\) dyn.*/\1 \2/p' "$d/log.lammps" | tail -1)
  lmp_steps=${last%% *}
  local quench
  quench=$(grep -c '^static check' "$d/log.lammps")
  if awk -v f="${last##* }" -v a="$acc" 'BEGIN { exit !(f <= a) }'; then
    lmp_status="static ($quench velocity zeroings)"
  else
    lmp_status="not static after $lmp_steps steps (${last##* } dyn)"
  fi
  if ! $py "$root/tools/lammps_peer.py" state "$d" > /dev/null 2> "$d/state.log"; then
    lmp_status="$lmp_status; state not converted: $(tail -1 "$d/state.log" | cut -c1-100)"
    return
  fi
  check "$d/state"
  lmp_force=$force lmp_contacts=$contacts lmp_stress=$stress
  lmp_status="$lmp_status, $chk"
  [ "$chk" = "check passed" ] && [ "${lmp_status#static}" != "$lmp_status" ] && lmp_ok=1
}

# path_start N DIR V: the path's start in V (the path's scenes by tools/solver_packing.sh, then
# gembem's frictionless relaxation of the packing, pressed to PATH_STRESS unless 0; or a copy of
# PATH_START): sets start (the start's run directory in V: relax_frictionless, pressed or given);
# on failure sets start_error and returns 1.
path_start() {
  local n=$1 d=$2 v=$3
  start=relax_frictionless
  [ "$PATH_STRESS" = 0 ] || start=pressed
  mkdir -p "$v"
  [ -z "$PATH_START" ] || { rm -rf "$v/given" && cp -r "$PATH_START" "$v/given" && start=given; }
  if ! env SOLVER=global LINEAR=umfpack NEWTON=line_search PACKING="$d/packing.csv" STATE="$v/$start" \
      "$root/tools/solver_packing.sh" "$build" "$v" "$n" 1 > /dev/null 2>&1 ||
     { [ "$start" != given ] &&
       ! timed "$v/relax_frictionless" "$v" "$build/gembem" run relax_frictionless.yaml -o relax_frictionless --overwrite --quiet; }; then
    start_error="the start (the path's scenes, gembem's frictionless relaxation) failed: see $v"
    return 1
  fi
  if [ "$start" = pressed ]; then
    sed -n '1,/^grains:/p' "$v/relax_frictionless.yaml" | grep -v '^grains:\|^#' > "$v/pressed.yaml"
    cat >> "$v/pressed.yaml" <<YAML
initial_state: relax_frictionless/state.yaml
$(grep '^solver:' "$v/relax_frictionless.yaml")
loading:
  - isotropic: {stress: $PATH_STRESS, steps: 5}
output: {measures_every: 0, localisation: false}
YAML
    if ! timed "$v/pressed" "$v" "$build/gembem" run pressed.yaml -o pressed --overwrite --quiet; then
      start_error="the start (gembem's frictionless compression to $PATH_STRESS dyn/cm) failed: see $v/pressed.log"
      return 1
    fi
  fi
}

# path_rows N DIR: the oedometric path (1 % vertical compression, side walls fixed, 25 deg
# between discs, frictionless walls) from a frictionless equilibrium of the packing that gembem's
# line search reaches (no tangential force: a start LAMMPS can take, which reads no tangential
# springs from a file): the packing relaxed, then pressed isotropically to PATH_STRESS (default
# 1e5 dyn/cm, in 5 steps; 0: relaxed only, a barely jammed start whose mean normal force is about
# twice the criterion at 1e3). gembem: 20 steps of de1 = 0.0005 (tools/solver_packing.sh's
# path.yaml), each to the static criterion. LAMMPS: the bottom and top walls moved in at a
# constant velocity over S time steps for each S of LAMMPS_PATH_STEPS (the loading rate), then
# relaxed to the static criterion (tools/lammps_peer.py --path-strain). Both end states are
# checked by tools/check_equilibrium.py; the last column compares the paths: the largest
# difference over the 20 strains of LAMMPS's wall stresses s1, s2 while loading (curve.txt, at
# 1/20 of S apart) with gembem's at rest (steps.csv), over gembem's s1 and s2 at 1 %.
path_rows() {
  local n=$1 d=$2 v=$2/path$sfx$psfx code secs mb its status gsecs=""
  echo
  if [ -n "$PATH_START" ]; then echo "Oedometric path from the state $PATH_START"
  else echo "Oedometric path from the frictionless packing $([ "$PATH_STRESS" = 0 ] && echo relaxed || echo "pressed to $PATH_STRESS dyn/cm")"; fi
  echo "| N | oedometric 1 %: code | status | iterations or steps (loading + relaxation) | wall s | peak MB | final largest force, checker [dyn] | this s / gembem s | contacts | s1, s2 at 1 % [dyn/cm] | path: largest difference in s1, s2 over gembem's at 1 % |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
  path_start "$n" "$d" "$v" || { echo "| $n | $start_error | | | | | | | | | |"; return; }
  timed "$v/path" "$v" "$build/gembem" run path.yaml -o path --overwrite --quiet
  code=$?
  read -r secs mb < <(secs_mb "$v/path")
  its=$(awk -F, 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next } $c["step"] > 0 { s += $c["iterations"]; w += $c["sweeps"] } END { printf "%d Newton, %d smoother steps", s, w }' "$v/path/steps.csv" 2>/dev/null)
  force=- contacts="" stress=""
  if [ $code = 0 ]; then
    check "$v/path"; status="converged, $chk"; gsecs=$secs
  else
    status="exit $code: $(grep -m1 . "$v/path.log" | sed 's/^gembem: //' | tr '|' '/' | cut -c1-120)"
  fi
  echo "| $n | gembem global, newton line_search, UMFPACK$gb_label | $status | $its | $secs | $mb | $force | 1 | $contacts | $stress | |"
  for S in $LAMMPS_PATH_STEPS; do
    lammps_run "$n" "$v/lammps_$S" "$LAMMPS_DT" "$LAMMPS_ZETA" "$LAMMPS_TDAMP" "$LAMMPS_VISCOUS" \
      "$v/$start/state_grains.csv" "$v/$start/state.yaml" --path-strain 0.01 --path-steps "$S"
    local ratio=- diff=-
    [ "$lmp_ok" = 1 ] && [ -n "$gsecs" ] && ratio=$(awk -v a="$lmp_secs" -v b="$gsecs" 'BEGIN { printf "%.2f", a / b }')
    [ -n "$gsecs" ] && [ -s "$v/lammps_$S/curve.txt" ] && diff=$($py - "$v/path/steps.csv" "$v/lammps_$S/curve.txt" <<'PY'
import csv, sys
g = [r for r in csv.DictReader(open(sys.argv[1])) if int(r["step"]) > 0]
l = [line.split() for line in open(sys.argv[2]) if line[0].isdigit()][1:]  # the 20 points past the start
if len(g) != 20 or len(l) != 20:
    sys.exit(f"expected 20 steps and 20 points, got {len(g)} and {len(l)}")
out = []
for col, k in (("s1", 2), ("s2", 3)):
    end = float(g[-1][col])
    out.append(max(abs(float(b[k]) - float(a[col])) for a, b in zip(g, l)) / end)
print(f"{100 * out[0]:.1f} %, {100 * out[1]:.1f} %")
PY
)
    local steps=""; [ -z "$lmp_steps" ] || steps="$S + $((lmp_steps - S))"
    echo "| $n | $lmp_label, walls moved in $S steps | $lmp_status | $steps | $lmp_secs | $lmp_mb | $lmp_force | $ratio | $lmp_contacts | $lmp_stress | $diff |"
  done
}

# shear_rows N DIR: the constant-volume biaxial shear (RUNS=shear; docs/benchmarks.md, "Shear
# path"): e1 from 0 to SHEAR_STRAIN (5 %) with e2 = -e1, bottom and top walls in, sides out, 25 deg
# between discs, frictionless walls, the static criterion a. The starts (SHEAR_START=own, the
# default): each code's own relaxation of the packing (gembem's line search + UMFPACK; LAMMPS's
# relaxation of the `lammps` row, ending in a restart file that keeps every contact's shear
# history); SHEAR_START=pressed: both from the path's start (path_start: gembem's frictionless
# equilibrium pressed to PATH_STRESS, friction on, no tangential force), LAMMPS after its own
# static check of it. gembem: `strain: {de1: e/n, de2: -e/n}` in n load steps for each n of
# SHEAR_STEPS, its solver `{SHEAR_SOLVER, threads, accuracy, SHEAR_SOLVER_EXTRA}`, every end state
# checked. LAMMPS (tools/lammps_peer.py shear): the walls at a constant velocity over S time steps
# for each S of LAMMPS_SHEAR_STEPS, global drag off, start velocities of seed 1 (LAMMPS_SHEAR_V0 of
# the top wall's speed), plus each S:SEED of LAMMPS_SHEAR_REPEAT; the walls' spring stresses
# every 0.25 % of e1. Loading CPU seconds: each loading is its own process (gembem from the
# start's state.yaml, LAMMPS from the restart), timed by /usr/bin/time (user + system).
# tools/shear_stats.py prints the rows and the statistics. SHEAR_REUSE=1 keeps the starts and
# the LAMMPS runs of an earlier invocation whose inputs are the same (gembem's shear runs always
# run): a new solver variant on exactly the same path, against the same LAMMPS runs.
shear_rows() {
  local n=$1 d=$2 v gstart status code secs mb cpu S seed steps reused ldir label
  v=$d/shear$sfx
  [ "$SHEAR_START" = own ] || v=$d/shear$sfx"_pressed"$psfx
  mkdir -p "$v"
  reuse() { [ "$SHEAR_REUSE" = 1 ]; }
  echo
  echo "Constant-volume biaxial shear to e1 = $SHEAR_STRAIN (e2 = -e1), the starts: $([ "$SHEAR_START" = own ] && echo "each code's own relaxation of the packing" || echo "the oedometric path's start, in $d/path$sfx$psfx")"
  echo "| N | shear start: code | status | iterations or steps | wall s | peak MB | final largest force, checker [dyn] | contacts | s1, s2 [dyn/cm] |"
  echo "|---|---|---|---|---|---|---|---|---|"
  # gembem's start
  local gstatus="" gits="" gsecs="" gmb=""
  if [ "$SHEAR_START" = own ]; then
    gstart=$v/start
    if reuse && [ -s "$gstart/state.yaml" ]; then
      gstatus="reused"
    elif env SOLVER=global LINEAR=umfpack NEWTON=line_search PACKING="$d/packing.csv" \
        "$root/tools/solver_packing.sh" "$build" "$v" "$n" 1 > /dev/null 2>&1 &&
        timed "$v/start" "$v" "$build/gembem" run relax_friction.yaml -o start --overwrite --quiet; then
      gstatus="converged"
    else
      echo "| $n | gembem's relaxation failed: see $v/start.log | | | | | | | |"; return
    fi
  else
    gstart=$d/path$sfx$psfx/pressed
    [ -n "$PATH_START" ] && gstart=$d/path$sfx$psfx/given
    [ "$PATH_STRESS" = 0 ] && [ -z "$PATH_START" ] && gstart=$d/path$sfx$psfx/relax_frictionless
    if reuse && [ -s "$gstart/state.yaml" ]; then gstatus="reused"
    elif path_start "$n" "$d" "$d/path$sfx$psfx"; then gstatus="converged"
    else echo "| $n | $start_error | | | | | | | |"; return
    fi
  fi
  [ -s "$gstart.time" ] && read -r gsecs gmb < <(secs_mb "$gstart") # the last step's run (pressed: the pressing)
  [ -s "$gstart/steps.csv" ] && gits=$(awk -F, 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next } $c["step"] > 0 { s += $c["iterations"] } END { print s + 0 }' "$gstart/steps.csv")
  check "$gstart"
  local gstress=$stress
  echo "| $n | gembem ($(basename "$gstart")) | $gstatus, $chk | $gits | $gsecs | $gmb | $force | $contacts | $stress |"
  # LAMMPS's start: its relaxation (or static check) of the packing or of gembem's start, with a restart file
  local lstart=$v/lammps_start grains=$d/packing.csv box=$d/packing.box.yaml
  [ "$SHEAR_START" = own ] || { grains=$gstart/state_grains.csv box=$gstart/state.yaml; }
  if reuse && [ -s "$lstart/start.restart" ] && [ -s "$lstart/state/state.yaml" ]; then
    check "$lstart/state"
    echo "| $n | $lmp_label | reused, $chk | | | | $force | $contacts | $stress |"
  else
    lammps_run "$n" "$lstart" "$LAMMPS_DT" "$LAMMPS_ZETA" "$LAMMPS_TDAMP" "$LAMMPS_VISCOUS" "$grains" "$box" --restart start.restart
    echo "| $n | $lmp_label | $lmp_status | $lmp_steps | $lmp_secs | $lmp_mb | $lmp_force | $lmp_contacts | $lmp_stress |"
    [ "$lmp_ok" = 1 ] && [ -s "$lstart/start.restart" ] || { echo "LAMMPS's start failed: no shear (see $lstart)"; return; }
    stress=$lmp_stress
  fi
  # a start far below the other's stress (an unjammed packing) makes the normalised paths incomparable
  awk -v a="$gstress" -v b="$stress" 'BEGIN { split(a, g, ", "); split(b, l, ", "); pg = g[1] + g[2]; pl = l[1] + l[2];
    exit !(pg > 0 && pl > 0 && (pl < 0.01 * pg || pg < 0.01 * pl)) }' &&
    echo "Warning: the two starts' mean stresses differ by more than 100 times (a packing unjammed by its relaxation): the paths are not comparable; SHEAR_START=pressed starts both codes from one jammed state"

  local man=$v/runs.tsv
  printf 'n\tcode\tlabel\tstatus\tsteps\tseed\tcurve\tcpu\twall\tmb\tforce\n' > "$man"
  # gembem: the load steps
  local solver="$SHEAR_SOLVER, threads: $THREADS, accuracy: $acc${SHEAR_SOLVER_EXTRA:+, $SHEAR_SOLVER_EXTRA}"
  for steps in $SHEAR_STEPS; do
    local scene=shear_$steps de
    de=$(awk -v e="$SHEAR_STRAIN" -v k="$steps" 'BEGIN { printf "%.17g", e / k }')
    { printf '# Written by tools/bench_peer.sh (RUNS=shear): constant-volume biaxial shear to e1 = %s (e2 = -e1)\n' "$SHEAR_STRAIN"
      printf '# in %s load steps from %s.\ngembem: 1\nunits: {length: cm, force: dyn}\n' "$steps" "$gstart"
      table3_materials 25 "$kn" "$kt"
      printf 'initial_state: %s/state.yaml\nsolver: {%s}\nloading:\n' "$gstart" "$solver"
      printf '  - strain: {de1: %s, de2: -%s, steps: %s}\n' "$de" "$de" "$steps"
      printf 'output: {measures_every: 0, localisation: false}   # the solver, not the per-step measures\n'
    } > "$v/$scene.yaml"
    timed "$v/$scene" "$v" "$build/gembem" run "$scene.yaml" -o "$scene" --overwrite --quiet
    code=$?
    read -r secs mb < <(secs_mb "$v/$scene")
    cpu=$(cpu_secs "$v/$scene")
    force=-
    if [ $code = 0 ]; then check "$v/$scene"; status="converged, $chk"
    else status="exit $code: $(grep -m1 . "$v/$scene.log" | sed 's/^gembem: //' | tr '|\t' '/ ' | cut -c1-120)"; fi
    label="gembem $steps load steps"
    [ "$solver" = "$SHEAR_SOLVER_DEFAULT, threads: 1, accuracy: $acc" ] || label="$label, solver {$solver}"
    printf '%s\tgembem\t%s\t%s\t%s\t\t%s\t%s\t%s\t%s\t%s\n' "$n" "$label" "$status" "$steps" "$v/$scene/steps.csv" "$cpu" "$secs" "$mb" "$force" >> "$man"
  done
  # LAMMPS: the rates with seed 1, then the repeats
  local points
  points=$(awk -v e="$SHEAR_STRAIN" 'BEGIN { printf "%d", e / 0.0025 + 0.5 }')
  for run in $(for S in $LAMMPS_SHEAR_STEPS; do echo "$S:1"; done) $LAMMPS_SHEAR_REPEAT; do
    S=${run%%:*} seed=${run##*:}
    ldir=$v/lammps_${S}_seed$seed
    mkdir -p "$ldir"
    reused=""
    if ! $py "$root/tools/lammps_peer.py" shear "$lstart" "$ldir/next" --steps "$S" --strain "$SHEAR_STRAIN" \
        --points "$points" --seed "$seed" --start-velocity "$LAMMPS_SHEAR_V0" > /dev/null 2> "$ldir/input.log"; then
      printf '%s\tlammps\t%s\t%s\t%s\t%s\t\t\t\t\t\n' "$n" "$lmp_label, walls moved in $S steps" \
        "no input: $(tail -1 "$ldir/input.log" | tr '|\t' '/ ' | cut -c1-100)" "$S" "$seed" >> "$man"
      continue
    fi
    if reuse && cmp -s "$ldir/next/in.shear" "$ldir/in.shear" && [ -s "$ldir/lmp.time" ] &&
       ! grep -q status "$ldir/lmp.time" && [ "$(grep -c '^[0-9]' "$ldir/curve.txt" 2>/dev/null)" = $((points + 1)) ]; then
      reused="reused, "
    else
      rm -f "$ldir"/{curve.txt,log.lammps,lmp.*}
      mv "$ldir/next/in.shear" "$ldir/next/params.yaml" "$ldir/"
      timed "$ldir/lmp" "$ldir" "${lmp_cmd[@]}" -nocite -in in.shear -log log.lammps -screen none
    fi
    rm -rf "$ldir/next"
    code=$(grep -q status "$ldir/lmp.time" && echo 1 || echo 0)
    read -r secs mb < <(secs_mb "$ldir/lmp")
    cpu=$(cpu_secs "$ldir/lmp")
    if [ "$code" = 0 ]; then
      status="${reused}sheared: $(sed -n 's/^sheared: step \([0-9]*\) e1 \(.*\)$/e1 = \2 in \1 steps/p' "$ldir/log.lammps")"
    else
      status="failed: $(grep -m1 ERROR "$ldir/log.lammps" 2>/dev/null | tr '|\t' '/ ' | cut -c1-120)"
    fi
    printf '%s\tlammps\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t-\n' "$n" "$lmp_label, walls moved in $S steps, seed $seed" \
      "$status" "$S" "$seed" "$ldir/curve.txt" "$cpu" "$secs" "$mb" >> "$man"
  done
  echo
  $py "$root/tools/shear_stats.py" "$man" --strain "$SHEAR_STRAIN" --curves "$v/curves.csv"
}

for n in $sizes; do
  d=$top/n$n
  mkdir -p "$d"
  if [ -s "$d/packing.csv" ] && [ -s "$d/packing.box.yaml" ]; then
    echo "n = $n: cached packing $d/packing.csv" >&2
  else
    if ! KEEP=1 "$root/tools/solver_packing.sh" "$build" "$d" "$n" 1 > /dev/null 2> "$d/packing.log"; then
      echo "| $n | packing | gb_packgen failed (see $d/packing.log) | | | | | | | |"
      continue
    fi
    echo "n = $n: $(tail -1 "$d/packing.log" | cut -c1-200)" >&2
  fi

  if [ "${SWEEP:-0}" = 1 ]; then
    echo "| N | dt factor | zeta_n | tangential damping | viscous | status | steps | wall s | largest force [dyn] | contacts | s1, s2 [dyn/cm] |"
    echo "|---|---|---|---|---|---|---|---|---|---|---|"
    for dt in ${SWEEP_DT:-0.2}; do for z in ${SWEEP_ZETA:-0 0.1 0.3 0.5 1.0}; do
      for td in ${SWEEP_TDAMP:-1}; do for v in ${SWEEP_VISCOUS:-0 0.003 0.01 0.02 0.05}; do
        LAMMPS_MAX_STEPS=${SWEEP_MAX_STEPS:-400000}
        lammps_run "$n" "$d/sweep/dt$dt-z$z-t$td-v$v" "$dt" "$z" "$td" "$v"
        echo "| $n | $dt | $z | $td | $v | $lmp_status | $lmp_steps | $lmp_secs | $lmp_force | $lmp_contacts | $lmp_stress |"
      done; done
    done; done
    continue
  fi

  if [[ " $RUNS " =~ \ (lammps|line_search|damped|reference)\  ]]; then
    echo "| N | code / solver | status | iterations or steps | wall s | peak MB | final largest force, checker [dyn] | LAMMPS s / this s | contacts | s1, s2 [dyn/cm] |"
    echo "|---|---|---|---|---|---|---|---|---|---|"
  fi
  lmp_secs="" lmp_ok=0
  if [[ " $RUNS " == *" lammps "* ]]; then
    lammps_run "$n" "$d/lammps$sfx" "$LAMMPS_DT" "$LAMMPS_ZETA" "$LAMMPS_TDAMP" "$LAMMPS_VISCOUS"
    echo "| $n | $lmp_label | $lmp_status | $lmp_steps | $lmp_secs | $lmp_mb | $lmp_force | 1 | $lmp_contacts | $lmp_stress |"
  fi
  for variant in line_search damped reference; do
    [[ " $RUNS " == *" $variant "* ]] || continue
    case $variant in
      line_search) env=(SOLVER=global LINEAR=umfpack NEWTON=line_search) label="gembem global, newton line_search, UMFPACK$gb_label" scene=relax_friction;;
      damped) env=(SOLVER=global LINEAR=cholmod NEWTON=damped) label="gembem global, damped, CHOLMOD$gb_label" scene=relax_friction;;
      reference)
        [ "$n" -le "$REF_MAX_N" ] || continue
        env=(SOLVER=reference) label="gembem reference iteration$gb_label" scene=relax_friction_reference;;
    esac
    v=$d/$variant$sfx
    env "${env[@]}" PACKING="$d/packing.csv" "$root/tools/solver_packing.sh" "$build" "$v" "$n" 1 > /dev/null 2>&1 || {
      echo "| $n | $label | tools/solver_packing.sh failed | | | | | | | |"; continue; }
    timed "$v/$scene" "$v" "$build/gembem" run "$scene.yaml" -o "$scene" --overwrite --quiet
    code=$?
    read -r secs mb < <(secs_mb "$v/$scene")
    if [ $code = 0 ]; then status=converged
    else status="exit $code: $(grep -m1 . "$v/$scene.log" | sed 's/^gembem: //' | tr '|' '/' | cut -c1-120)"; fi
    its=""
    [ -s "$v/$scene/steps.csv" ] && its=$(awk -F, 'NR == 1 { for (k = 1; k <= NF; k++) c[$k] = k; next } $c["step"] > 0 { s += $c["iterations"] } END { print s + 0 }' "$v/$scene/steps.csv")
    if [ $code != 0 ]; then # the failed step's iterations are not in steps.csv: its cap
      cap=$(sed -n 's/.*did not converge in \([0-9]*\) iterations.*/\1/p' "$v/$scene.log" | head -1)
      [ -z "$cap" ] || { its="$((its + cap)) (the cap reached)"; status="exit $code: not converged in $cap iterations"; }
    fi
    ratio=- force=- contacts="" stress=""
    if [ -s "$v/$scene/state.yaml" ] && [ $code = 0 ]; then
      check "$v/$scene"
      status="$status, $chk"
      [ "$chk" = "check passed" ] && [ "$lmp_ok" = 1 ] &&
        ratio=$(awk -v a="$lmp_secs" -v b="$secs" 'BEGIN { printf "%.2f", a / b }')
    else # not converged: gembem's own figure for its last iterate, not checked
      force=$(sed -n 's/.*largest fixing force \([0-9.eE+-]*\),.*/\1/p' "$v/$scene.log" | head -1)
      force=${force:+"$force (gembem's own, not checked)"}
      force=${force:--}
    fi
    echo "| $n | $label | $status | $its | $secs | $mb | $force | $ratio | $contacts | $stress |"
  done
  [[ " $RUNS " != *" path "* ]] || path_rows "$n" "$d"
  [[ " $RUNS " != *" shear "* ]] || shear_rows "$n" "$d"
done
exit 0
