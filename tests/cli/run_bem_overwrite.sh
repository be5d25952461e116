#!/usr/bin/env bash
# gembem bem -o OUTDIR: a new or empty OUTDIR is written; a non-empty one is refused (exit 2, a
# message naming --overwrite, nothing in it touched) unless --overwrite, which replaces its files;
# a file in OUTDIR's place is refused.
set -u
gembem=$1; root=$(cd "$(dirname "$0")/../.." && pwd)
scene=$root/tests/bem/scenes/good_base.yaml
source "$root/tools/lib.sh"
gb_test_begin

"$gembem" bem "$scene" -o "$out/new" >/dev/null && [ -f "$out/new/run_info.yaml" ] && ok "a new directory is written" \
  || bad "a new directory: not written"
mkdir "$out/empty"
"$gembem" bem "$scene" -o "$out/empty" >/dev/null && [ -f "$out/empty/boundary.csv" ] && ok "an empty directory is written" \
  || bad "an empty directory: not written"
echo "not gembem's" > "$out/new/mine.txt"; echo stale > "$out/new/run_info.yaml"
msg=$("$gembem" bem "$scene" -o "$out/new" 2>&1 >/dev/null); code=$?
if [ $code -eq 2 ] && [[ $msg == *"output directory $out/new exists and is not empty; choose another or pass --overwrite"* ]] \
   && [ "$(cat "$out/new/run_info.yaml")" = stale ]; then ok "a non-empty directory is refused, untouched: $msg"
else bad "a non-empty directory: exit $code, '$msg', run_info.yaml '$(cat "$out/new/run_info.yaml")'"; fi
"$gembem" bem "$scene" -o "$out/new" --overwrite >/dev/null; code=$?
if [ $code -eq 0 ] && grep -q '^  system_rcond: ' "$out/new/run_info.yaml" && [ -f "$out/new/mine.txt" ]; then
  ok "--overwrite replaces the outputs (other files left)"
else bad "--overwrite: exit $code, run_info.yaml '$(head -1 "$out/new/run_info.yaml")'"; fi
touch "$out/file"
msg=$("$gembem" bem "$scene" -o "$out/file" --overwrite 2>&1 >/dev/null); code=$?
[ $code -eq 2 ] && [[ $msg == *"exists and is not a directory"* ]] && ok "a file in OUTDIR's place is refused: $msg" \
  || bad "a file as OUTDIR: exit $code, '$msg'"
"$gembem" bem --help | grep -q -- '--overwrite' && ok "the usage names --overwrite" || bad "the usage lacks --overwrite"

rm -rf "$out"
echo "$passed passed, $fail failed"
[ $fail -eq 0 ]
