#!/usr/bin/env bash
# Every pack scene in tests/pack/bad is refused before any computation: exit status 2, the message
# of the .expect file beside it (file:line:column and what was expected), and no directory written.
# Then a directory that is not empty is refused without --overwrite, and left as it was.
#   run_pack_bad.sh GEMBEM
set -u
gembem=$1; dir=$(cd "$(dirname "$0")" && pwd)
source "$dir/../../tools/lib.sh"
out=$(mktemp -d); fail=0; n=0
trap 'rm -rf "$out"' EXIT
for scene in "$dir"/bad/*.yaml; do expect_refused pack "$scene" "$(cat "${scene%.yaml}.expect")"; done
n=$((n + 1)); mkdir "$out/full"; echo keep > "$out/full/file"
msg=$("$gembem" pack "$dir/box_growth.yaml" -o "$out/full" 2>&1 >/dev/null); code=$?
if [ $code -ne 2 ] || [ "$(ls "$out/full")" != file ]; then
  echo "FAIL a full directory: exit status $code ($msg), files $(ls "$out/full")"; fail=$((fail + 1))
else
  echo "ok   full directory: $msg"
fi
echo "$((n - fail)) of $n bad packs refused as expected"
[ $fail -eq 0 ]
