# Shell functions shared by the scripts of tools/ and the shell tests (sourced; bash).

# A shell test's scratch directory $out, its counters and its checks' lines (tests/cli).
gb_test_begin() { out=$(mktemp -d); fail=0; passed=0; }
ok() { passed=$((passed + 1)); echo "ok   $1"; }
bad() { fail=$((fail + 1)); echo "FAIL $1"; }
# Its end: the scratch directory removed if every check passed (else named), the counts, the status.
gb_test_end() {
  [ $fail -eq 0 ] && rm -rf "$out" || echo "outputs kept in $out"
  echo "$passed passed, $fail failed"
  [ $fail -eq 0 ]
}

# A scene refused before any computation: `$gembem SUBCOMMAND SCENE -o $out/NAME` exits with 2, a
# message holding EXPECT, and no directory NAME; adds to the counts n and fail, prints a line.
#   expect_refused SUBCOMMAND SCENE EXPECT
expect_refused() {
  local name msg code
  name=$(basename "$2" .yaml); n=$((n + 1))
  msg=$("$gembem" "$1" "$2" -o "$out/$name" 2>&1 >/dev/null); code=$?
  if [ $code -ne 2 ]; then echo "FAIL $name: exit status $code, expected 2 ($msg)"; fail=$((fail + 1)); return; fi
  case "$msg" in *"$3"*) ;; *) echo "FAIL $name: message '$msg' lacks '$3'"; fail=$((fail + 1)); return;; esac
  if [ -e "$out/$name" ]; then echo "FAIL $name: the directory was created"; fail=$((fail + 1)); return; fi
  echo "ok   $name: $msg"
}

# The materials of Kishino (1989) Table 3: kn, kt = 1e8, 7e7 dyn/cm, grain-grain friction $1 deg
# (default 25), frictionless walls.
table3_materials() { # [FRICTION_DEG (25)] [KN (1.0e8)] [KT (7.0e7)]
  cat <<YAML
materials:
  grain_grain: {kn: ${2:-1.0e8}, kt: ${3:-7.0e7}, friction_deg: ${1:-25}}
  grain_wall:  {kn: ${2:-1.0e8}, kt: ${3:-7.0e7}, friction_deg: 0}
YAML
}
# The head of a scene in cm and dyn with those materials and the grains of file $1; the box or
# state, solver and loading follow.
table3_scene_head() {
  printf 'gembem: 1\nunits: {length: cm, force: dyn}\n'
  table3_materials
  printf 'grains: {file: %s}\n' "$1"
}

# The benchmark scripts' arguments, [BUILD_DIR] [N ...]: $root, $build (default build, relative to
# the repository's root unless absolute), $sizes (default 1000 10000 100000), $steps ($STEPS,
# default 4) and $out (runs/bench_gem).
bench_args() {
  root=$(cd "$(dirname "$0")/.." && pwd)
  build=${1:-build}
  case $build in /*) ;; *) build=$root/$build;; esac
  shift || true
  sizes=${*:-1000 10000 100000}
  steps=${STEPS:-4}
  out=$root/runs/bench_gem
}

# Whether run directories A and B hold the same bytes in every file but run_info.yaml (times),
# .lock (its holder), steps.csv's seconds column and pack_info.yaml's `made` and `seconds` lines
# (wall time); what differs goes to DIFF.
gb_same_run_dirs() { # A B DIFF
  diff -r -x run_info.yaml -x steps.csv -x pack_info.yaml -x .lock "$1" "$2" > "$3" 2>&1 || return 1
  local drop='NR == 1 { for (i = 1; i <= NF; i++) if ($i == "seconds") k = i } k { $k = "" } 1' f
  for f in steps.csv pack_info.yaml; do
    [ -f "$1/$f" ] || [ -f "$2/$f" ] || continue
    if [ $f = steps.csv ]; then
      cmp -s <(awk -F, -v OFS=, "$drop" "$1/$f") <(awk -F, -v OFS=, "$drop" "$2/$f") && continue
    else cmp -s <(grep -Ev '^(made|seconds):' "$1/$f") <(grep -Ev '^(made|seconds):' "$2/$f") && continue; fi
    echo "$f differs (wall times aside)" >> "$3"; return 1
  done
}
