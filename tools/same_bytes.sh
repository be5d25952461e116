#!/usr/bin/env bash
# Whether two builds of gembem give the same bytes: for a change that must not move a number (a
# reorganisation of the code). Runs each case with BUILD_A's gembem, then with BUILD_B's, in the
# same directory (so that paths written into the outputs agree), and compares the run directories
# file by file (tools/lib.sh's gb_same_run_dirs: run_info.yaml and steps.csv's seconds aside).
#   tools/same_bytes.sh BUILD_A BUILD_B [OUT] [CASE ...]
# OUT (default runs/same_bytes) keeps OUT/A/CASE and OUT/B/CASE. The cases (default: all):
#   demo        the demo's three runs (examples/demo: gembem pack, settle, compress; 300 grains)
#   three_discs Kishino (1989) case 1 (validation/three_discs/case1.yaml)
#   biaxial122  the 122-disc biaxial at constant mean stress, 100 shear steps from its stored
#               packing (validation/biaxial122/test_shear.yaml, steps 20 -> 100)
#   cavity      the hybrid paper's 27-grain cavity packing (validation/cavity_packing/scene.yaml)
#   path1e4     1e4 discs (tools/solver_packing.sh, seed 1): a relaxation with friction by the
#               global solver, then its 20-step oedometric path (UMFPACK, line search)
# KEEP_A=1: BUILD_A's runs already in OUT/A are kept, not run again (a baseline made once).
# Prints a line per case and run directory, exits 1 if any differs. OPENBLAS_NUM_THREADS=1.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
source "$root/tools/lib.sh"
[ $# -ge 2 ] || { echo "usage: tools/same_bytes.sh BUILD_A BUILD_B [OUT] [CASE ...]" >&2; exit 2; }
a=$(cd "$1" && pwd) b=$(cd "$2" && pwd)
mkdir -p "${3:-$root/runs/same_bytes}"
out=$(cd "${3:-$root/runs/same_bytes}" && pwd)
shift $(($# >= 3 ? 3 : 2))
cases=("$@")
[ ${#cases[@]} -gt 0 ] || cases=(demo three_discs biaxial122 cavity path1e4)
export OPENBLAS_NUM_THREADS=1

# One case with BUILD's executables into the directory $out/run/CASE.
run_case() { # BUILD CASE
  local build=$1 d=$out/run/$2
  rm -rf "$d"; mkdir -p "$d"
  case $2 in
    demo) # demo.py's scenes and order, without its figures
      GEMBEM=$build/gembem PYTHONPATH=$root/python /usr/bin/python3 -c '
import sys; sys.path.insert(0, sys.argv[1] + "/examples/demo")
import demo; demo.run_all(sys.argv[2], quiet=True)' "$root" "$d" ;;
    three_discs) "$build/gembem" run "$root/validation/three_discs/case1.yaml" -o "$d/run" --quiet ;;
    biaxial122)
      sed -e 's/steps: 20,/steps: 100,/' -e "s|initial_state: test_state/|initial_state: $root/validation/biaxial122/test_state/|" \
        "$root/validation/biaxial122/test_shear.yaml" > "$d/scene.yaml"
      grep -q "steps: 100," "$d/scene.yaml" && "$build/gembem" run "$d/scene.yaml" -o "$d/run" --quiet ;;
    cavity) "$build/gembem" run "$root/validation/cavity_packing/scene.yaml" -o "$d/run" --quiet ;;
    path1e4)
      LINEAR=umfpack NEWTON=line_search "$root/tools/solver_packing.sh" "$build" "$d" 10000 1 > /dev/null &&
        "$build/gembem" run "$d/relax_friction.yaml" -o "$d/relax_friction" --quiet &&
        "$build/gembem" run "$d/path.yaml" -o "$d/path" --quiet ;;
    *) echo "same_bytes.sh: no case '$2' (demo three_discs biaxial122 cavity path1e4)" >&2; exit 2 ;;
  esac
}

differ=0
for c in "${cases[@]}"; do
  for side in A B; do
    build=$a; [ $side = A ] || build=$b
    [ $side = A ] && [ "${KEEP_A:-0}" = 1 ] && [ -d "$out/A/$c" ] && continue
    start=$(date +%s)
    # (gembem's warnings to OUT/SIDE.CASE.log; in a condition, so a failing case is reported)
    # that build's library, also where the build was copied (bin and library in one directory)
    if ! LD_LIBRARY_PATH=$build/src:$build run_case "$build" "$c" 2> "$out/$side.$c.log"; then
      echo "FAIL  $c: $side's run failed: $(tail -c 400 "$out/$side.$c.log")"; differ=1; continue 2
    fi
    rm -rf "${out:?}/$side/$c"; mkdir -p "$out/$side"; mv "$out/run/$c" "$out/$side/$c"
    echo "$c: $side ran in $(($(date +%s) - start)) s"
  done
  # every run directory of the case (a directory with a steps.csv or a pack_info.yaml)
  while read -r dir; do
    rel=${dir#"$out/A/"}
    if gb_same_run_dirs "$dir" "$out/B/$rel" "$out/diff"; then
      echo "same  $rel ($(find "$dir" -type f | wc -l) files)"
    else echo "DIFF  $rel: $(head -c 400 "$out/diff")"; differ=1; fi
  done < <(find "$out/A/$c" \( -name steps.csv -o -name pack_info.yaml \) -printf '%h\n' | sort -u)
done
[ $differ -eq 0 ]
