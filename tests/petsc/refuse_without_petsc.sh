#!/usr/bin/env bash
# A gembem built without PETSc refuses solver.linear: petsc at the scene's check: exit 2, the
# scene's line and column, what to install, and no run directory.
#   refuse_without_petsc.sh GEMBEM
set -u
gembem=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$root/tests/scene.sh"
scene_edit "$root/tests/hybrid/load_grains.yaml" -o "$work/scene.yaml" --set solver.linear=petsc
"$gembem" run "$work/scene.yaml" -o "$work/run" > "$work/log" 2>&1
rc=$?
msg="built without PETSc; install libpetsc-real-dev and rebuild"
if [ $rc -eq 2 ] && grep -q "scene.yaml:[0-9]*:[0-9]*: .*$msg" "$work/log" && [ ! -e "$work/run" ]; then
  echo "ok   $(cat "$work/log")"
  exit 0
fi
echo "FAIL expected exit 2 with '$msg' and no run directory, got $rc: $(cat "$work/log")"
exit 1
