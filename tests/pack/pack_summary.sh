#!/usr/bin/env bash
# gembem pack's summary says when the drawn radii were rescaled, and by how much: box_oversized.yaml's
# grains are shrunk to 0.349928 of their size (its comment computes it); the summary names 0.35,
# pack_info.yaml's radius_scale is that scale to 1e-9, and the exit status is 0.
#   pack_summary.sh GEMBEM
set -u
gembem=$1; dir=$(cd "$(dirname "$0")" && pwd)
out=$(mktemp -d); fail=0
trap 'rm -rf "$out"' EXIT
said=$("$gembem" pack "$dir/box_oversized.yaml" -o "$out/pack") || { echo "FAIL gembem pack exit $?"; exit 1; }
echo "$said"
case $said in
  *"the drawn radii shrunk to 0.35 of their size"*) echo "ok   the summary says the radii were shrunk to 0.35" ;;
  *) echo "FAIL the summary does not say the radii were shrunk to 0.35"; fail=1 ;;
esac
scale=$(sed -n 's/^radius_scale: \([^ ]*\).*/\1/p' "$out/pack/pack_info.yaml")
if awk -v s="$scale" 'BEGIN { e = sqrt(0.82 / atan2(0, -1)) / 1.46; exit !(s - e < 1e-9 && e - s < 1e-9) }'; then
  echo "ok   pack_info.yaml radius_scale $scale"
else
  echo "FAIL pack_info.yaml radius_scale '$scale', expected sqrt(0.82 / pi) / 1.46"; fail=1
fi
exit $fail
