#!/usr/bin/env bash
# A million coincident discs (a grains file of one line repeated) are refused at admission, exit 2,
# naming the first offender and its partner by their lines, within bounded time and memory: the
# pair check runs on the cell grid without a pair list (src/scene/admit.c). Every pair of the file
# overlaps by 2 r = 0.2 (the centres coincide), twice the radius: grain 1 on the CSV's line 3
# (line 1 is the header, grain 0 on line 2) against grain 0 on line 2, the first pair in index order.
# The address space is capped at 2 GB (the whole pair list would need 32 TB) and the time at 60 s.
# Under AddressSanitizer (ASAN_OPTIONS set, tools/test.sh --sanitize) only the time is capped.
#   run_coincident.sh GEMBEM
set -u
gembem=$1; dir=$(dirname "$0"); out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
sed 's/grains_overlap.csv/same.csv/' "$dir/bad/grains_csv_overlap.yaml" > "$out/same.yaml"
{ echo x,y,r; yes 2.0,2.0,0.1 | head -n 1000000; } > "$out/same.csv"
# (not under AddressSanitizer, whose shadow memory alone reserves terabytes of address space)
cap=2000000; [ -n "${ASAN_OPTIONS:-}" ] && cap=unlimited
msg=$(ulimit -v $cap; timeout 60 "$gembem" run "$out/same.yaml" -o "$out/run" 2>&1 >/dev/null); code=$?
echo "$msg"
[ $code -eq 2 ] || { echo "FAIL: exit status $code, expected 2"; exit 1; }
want="same.csv:3:1: grain 1 (x 2, y 2, r 0.1) overlaps grain 0 (line 2) by 0.2 (2 of the smaller radius)"
case "$msg" in *"$want"*) ;; *) echo "FAIL: the message lacks '$want'"; exit 1;; esac
[ ! -e "$out/run" ] || { echo "FAIL: the run directory was created"; exit 1; }
echo ok
