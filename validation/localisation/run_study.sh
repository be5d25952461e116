#!/bin/sh
# The localisation study: packs the grains, runs every granular case of the sweep and the two
# reference fillings (empty cavity, elastic discs), then draws the figures.
#   validation/localisation/run_study.sh [CASE ...]      (from the repository root; default: the
#                                                         8 cases of the sweep)
#   validation/localisation/run_study.sh extended        the extended cases (study.py extended)
# Runs go to runs/localisation/NAME/run (git-ignored); a run that stops (exit 3: a step did not
# converge) is kept and reported, and tried again with the top's steps halved (NAME/run_refine2);
# an extended case is run by run_continued.py instead (NAME/segNN: continued past its stalls). Needs build/ (cmake --build build). Environment: JOBS (default 1)
# runs that many cases at once.
set -u
cd "$(dirname "$0")/../.."
ROOT=$(pwd)
HERE=validation/localisation
OUT=runs/localisation
PY=/usr/bin/python3
GEMBEM=build/gembem
DISC=build/validation/localisation/elastic_disc
JOBS=${JOBS:-1}
export OPENBLAS_NUM_THREADS=1
[ -x "$GEMBEM" ] && [ -x "$DISC" ] || { echo "build first: cmake --build build" >&2; exit 1; }
mkdir -p "$OUT"
start=$(date +%s)


if [ "${1:-}" = "--one" ]; then # one granular case: --one NAME [...] (the rest of study.py's line)
    dir=$OUT/$2
    mkdir -p "$dir"
    args=$($PY $HERE/study.py pack "$2")
    if [ ! -s "$dir/grains.csv" ] || [ "$(cat "$dir/grains.args" 2>/dev/null)" != "$args" ]; then # (seeded: the same args, the same grains)
        # shellcheck disable=SC2086
        $PY $HERE/pack_cavity.py $args > "$dir/grains.csv" 2>/dev/null || exit 1
        echo "$args" > "$dir/grains.args"
    fi
    if $PY $HERE/study.py extended | grep "^$2 " > /dev/null; then # an extended case: continued past its stalls
        $PY $HERE/run_continued.py "$2" "$dir" "$ROOT/meshes/square_cavity_sides.geo" "$ROOT/$GEMBEM"
        exit 0
    fi
    $PY $HERE/study.py scene "$2" "$dir" "$ROOT/meshes/square_cavity_sides.geo"
    t0=$(date +%s)
    $GEMBEM run "$dir/scene.yaml" -o "$dir/run" --overwrite --quiet > "$dir/gembem.log" 2>&1
    rc=$?
    echo "$2 exit $rc $(( $(date +%s) - t0 )) s $(tail -n 1 "$dir/gembem.log")" | tee "$dir/status.txt"
    rm -rf "$dir/run_refine2" "$dir/status_refine2.txt"
    if [ $rc -eq 3 ]; then # a step did not converge: a second attempt with the top's steps halved
        $PY $HERE/study.py scene "$2" "$dir" "$ROOT/meshes/square_cavity_sides.geo" 2
        t0=$(date +%s)
        $GEMBEM run "$dir/scene_refine2.yaml" -o "$dir/run_refine2" --overwrite --quiet > "$dir/gembem_refine2.log" 2>&1
        rc=$?
        echo "$2 (steps halved) exit $rc $(( $(date +%s) - t0 )) s $(tail -n 1 "$dir/gembem_refine2.log")" |
            tee "$dir/status_refine2.txt"
    fi
    exit 0
fi

$PY $HERE/study.py cases > "$OUT/cases.txt"
$PY $HERE/study.py extended >> "$OUT/cases.txt"
if [ "${1:-}" = "extended" ]; then
    $PY $HERE/study.py extended > "$OUT/cases_run.txt"
elif [ $# -gt 0 ]; then # only the cases named
    for c in "$@"; do grep "^$c " "$OUT/cases.txt" || echo "unknown case $c" >&2; done > "$OUT/cases_run.txt"
else # the sweep (the extended cases take a few minutes each: run them by 'extended')
    $PY $HERE/study.py cases > "$OUT/cases_run.txt"
fi
xargs -P "$JOBS" -L 1 "$ROOT/$HERE/run_study.sh" --one < "$OUT/cases_run.txt"

# The references from the boundary element module alone, on the granular cases' loading.
set -- $($PY $HERE/study.py load)
P=$1 STEPS_P=$2 UY=$3 STEPS=$4
mkdir -p "$OUT/reference"
$DISC disc_mu=0 pressure="$P" steps_p="$STEPS_P" top_uy="$UY" steps="$STEPS" out="$OUT/reference/empty" || exit 1
$PY $HERE/study.py disc_moduli > "$OUT/reference/discs.txt"
while read -r name g nu; do
    $DISC disc_mu="$g" disc_nu="$nu" pressure="$P" steps_p="$STEPS_P" top_uy="$UY" steps="$STEPS" \
        out="$OUT/reference/disc_$name" || exit 1
done < "$OUT/reference/discs.txt"
echo "study: $(( $(date +%s) - start )) s" | tee "$OUT/time.txt"
$PY $HERE/figures.py
