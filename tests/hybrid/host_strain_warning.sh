#!/usr/bin/env bash
# The run warns when the linear host leaves its range: tests/hybrid/host_loading.yaml (a square
# host 10 x 10 whose top is pushed down in 3 steps, an empty cavity) as it is (top moved by 0.003:
# no warning) and pushed 100 times as far (0.3, a nominal strain of 3 %: the cavity past 2 %),
# where stderr and run_info.yaml's warnings give the cavity's strain: the largest principal strain
# of the affine map that fits its elements' displacements. That strain is fitted here again from
# host_boundary.csv (least squares over the cavity's midpoints) and must agree to the digits
# printed, and exceed the nominal 3 %.
#   host_strain_warning.sh GEMBEM
set -u
gembem=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
source "$root/tools/lib.sh"
source "$root/tests/scene.sh"
source "$root/tests/csv.sh"
gb_test_begin
scene_edit "$root/tests/hybrid/host_loading.yaml" -o "$out/small.yaml"
scene_edit "$root/tests/hybrid/host_loading.yaml" -o "$out/large.yaml" \
  --set 'loading.0.host_displacement.increments={top: [0, -0.1]}'
"$gembem" run "$out/small.yaml" -o "$out/small" --quiet 2> "$out/small.err" || bad "the small run failed"
"$gembem" run "$out/large.yaml" -o "$out/large" --quiet 2> "$out/large.err" || bad "the large run failed"
if grep -q "cavity is strained" "$out/small.err" "$out/small/run_info.yaml"; then
  bad "the small push warns of the host's strain"
else ok "no warning at a strain of about 0.03 %"; fi
said=$(sed -n 's/.*warning: the host.s cavity is strained by \([0-9.e+-]*\) %.*/\1/p' "$out/large.err")
if [ -n "$said" ] && grep -q "cavity is strained by $said %" "$out/large/run_info.yaml"; then
  ok "the large push warns on stderr and in run_info.yaml: $said %"
else bad "the large push does not warn of the host's strain: $(cat "$out/large.err")"; fi
# the affine map u = A x + b that fits the cavity's midpoints' displacements, its symmetric
# part's largest principal value in magnitude
mine=$(csv_awk 'FNR > 1 && $col("group") == "cavity" {
    k = n++; x[k] = $col("x"); y[k] = $col("y"); u[k] = $col("ux"); v[k] = $col("uy"); mx += x[k]; my += y[k]
  } END {
    mx /= n; my /= n
    for (i = 0; i < n; i++) {
      dx = x[i] - mx; dy = y[i] - my
      cxx += dx * dx; cxy += dx * dy; cyy += dy * dy; ux += u[i] * dx; uy += u[i] * dy; vx += v[i] * dx; vy += v[i] * dy
    }
    d = cxx * cyy - cxy * cxy
    a11 = (ux * cyy - uy * cxy) / d; a12 = (uy * cxx - ux * cxy) / d
    a21 = (vx * cyy - vy * cxy) / d; a22 = (vy * cxx - vx * cxy) / d
    m = (a11 + a22) / 2; r = sqrt((a11 - a22) * (a11 - a22) / 4 + (a12 + a21) * (a12 + a21) / 4)
    e = m + r; if (e < 0) e = -e; f = m - r; if (f < 0) f = -f; if (f > e) e = f
    printf "%.3g", 100 * e
  }' "$out/large/host_boundary.csv")
if [ -n "$said" ] && [ "$mine" = "$said" ] && awk -v s="$said" 'BEGIN { exit !(s > 3) }'; then
  ok "host_boundary.csv's displacements give the same $mine %, above the nominal 3 %"
else bad "host_boundary.csv gives $mine %, the warning '$said' (expected the same, above 3)"; fi
gb_test_end
