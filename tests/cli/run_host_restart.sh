#!/usr/bin/env bash
# A hybrid run restarts from its state.yaml (the host's cavity displacements and boundary
# particles, every group's current values, the remote stress, the solver's damping):
# 1. tests/hybrid/load_grains.yaml (27 grains, a confining pressure, then the top pushed) in one
#    run, and as stage 1 (relax, pressure) + a restart for stage 2 (the top): the final grain
#    positions and rotations of the grains held by two contacts or more, the host's cavity
#    displacements and host_steps.csv's rows of stage 2 equal to 1e-9 of each column's largest
#    value, the iterations per step within 2, the host's boundary values in state.yaml identical.
#    Not bit for bit: the restart builds its pair list afresh, so sums run in another order, and
#    the rounding steers the iteration slightly otherwise (an iteration more or less); the
#    accuracy a = 1e-9 kgf against stiffnesses of 1e3-1e5 kgf/cm fixes the positions to about
#    1e-12 cm. A grain left with one contact or none is in equilibrium wherever its path leaves it
#    (it touches with no force), so its place is not compared.
# 2. The same for tests/hybrid/load_grains_remote.yaml (an infinite plane, the remote stress
#    grown in 3 steps: 2 + a restart for 1), with friction and kt on the boundary particles so
#    that their contacts carry tangential forces through the restart. The cavity's rows in
#    host_steps.csv are zero to rounding there (no net force on a cavity in an infinite plane,
#    no mean displacement beyond its rigid one): they are compared with the scale of its element
#    displacements (1e-4 cm; largest 6.4e-4) and of the grains' forces on it (1 kgf; up to 42).
# 3. A state that does not fit the scene is refused (exit 2, file:line:column, no run directory):
#    another element count, another kind of condition, a particle off its element, a state
#    without a host, a scene without a host, a state of a host that followed its boundary
#    (host.updated_lagrangian: its moved mesh is not in a state file).
set -u
gembem=$1; root=$(cd "$(dirname "$0")/../.." && pwd)
source "$root/tests/csv.sh"
source "$root/tests/scene.sh"
source "$root/tools/lib.sh"
gb_test_begin

# Per column of two CSV files: the largest |a - b| over the largest |a| (first file's header), or
# over the column's floor if larger (floors "col:value,..."); exits 1 if any exceeds tol. Columns
# that are words must be equal.
cmp_csv() { # a b tol label [floors]
  awk -F, -v tol="$3" -v label="$4" -v floors="${5:-}" '
    FNR == 1 { for (c = 1; c <= NF; c++) h[c] = $c; next }
    NR == FNR { for (c = 1; c <= NF; c++) a[FNR, c] = $c; n = NF; rows = FNR; next }
    { seen = FNR
      for (c = 1; c <= NF; c++) {
        if ($c !~ /^[-+0-9.eE]+$/) { if ($c != a[FNR, c]) words++; continue }
        d = $c - a[FNR, c]; if (d < 0) d = -d; if (d > dm[c]) dm[c] = d
        v = a[FNR, c] + 0; if (v < 0) v = -v; if (v > vm[c]) vm[c] = v } }
    END { nf = split(floors, fl, ","); for (k = 1; k <= nf; k++) { split(fl[k], kv, ":"); floor[kv[1]] = kv[2] + 0 }
          for (c = 1; c <= n; c++) if (vm[c] < floor[h[c]]) vm[c] = floor[h[c]]
          worst = 0; line = ""
          for (c = 1; c <= n; c++) { r = (vm[c] > 0 ? dm[c] / vm[c] : dm[c]); if (r > worst) worst = r
                                      line = line sprintf(" %s %.2g", h[c], r) }
          printf "%s: relative differences per column:%s\n", label, line
          exit (worst > tol || words > 0 || seen != rows) }' "$1" "$2"
}

# one scene, split after stage 1's first `split` steps into two runs: the scene edits (scene_edit
# arguments) of the arrays all (the one-go run and both stages), s1 (stage 1) and s2 (stage 2, whose
# grains come from stage 1's state instead)
restart_case() { # name scene one-go-first-row-of-stage2 [floors]
  local name=$1 scene=$2 first=$3 floors=${4:-} d=$out/$1
  mkdir -p "$d"
  scene_edit "$scene" -o "$d/one.yaml" "${all[@]}"
  scene_edit "$d/one.yaml" -o "$d/s1.yaml" "${s1[@]}"
  scene_edit "$d/one.yaml" -o "$d/s2.yaml" --delete grains --add initial_state=stage1/state.yaml "${s2[@]}"
  "$gembem" run "$d/one.yaml" -o "$d/one" --quiet || { bad "$name: the one-go run failed"; return; }
  "$gembem" run "$d/s1.yaml" -o "$d/stage1" --quiet || { bad "$name: stage 1 failed"; return; }
  "$gembem" run "$d/s2.yaml" -o "$d/stage2" --quiet || { bad "$name: the restart failed"; return; }
  # the grains held by two contacts or more in the one-go run (grain ids are 0-based rows)
  csv_awk 'NR > 1 { c[$col("i")]++; c[$col("j")]++ } END { for (k in c) if (c[k] >= 2 && k ~ /^[0-9]+$/) print k }' \
    "$d/one/state_contacts.csv" > "$d/held"
  for f in one stage2; do
    awk -F, 'NR == FNR { held[$1] = 1; next } FNR == 1 || held[FNR - 2]' "$d/held" "$d/$f/state_grains.csv" > "$d/g_$f"
  done
  cmp_csv "$d/g_one" "$d/g_stage2" 1e-9 "$name grains ($(wc -l < "$d/held") held by two contacts or more)" \
    && ok "$name: final grains equal (1e-9)" || bad "$name: final grains differ"
  cmp_csv "$d/one/state_host.csv" "$d/stage2/state_host.csv" 1e-9 "$name host" \
    && ok "$name: host cavity displacements equal (1e-9)" || bad "$name: host cavity displacements differ"
  # host_steps.csv: the one-go rows from step `first` on against the restart's, step numbers aside
  no_step() { # FIRST FILE: its header and rows from step FIRST on, without the step column
    csv_awk -v f="$1" 'NR == 1 || $col("step") >= f {
      s = ""; sep = ""; for (k = 1; k <= NF; k++) if (k != col("step")) { s = s sep $k; sep = "," }
      print s }' "$2"
  }
  no_step "$first" "$d/one/host_steps.csv" > "$d/h1"
  no_step 0 "$d/stage2/host_steps.csv" > "$d/h2"
  cmp_csv "$d/h1" "$d/h2" 1e-9 "$name host_steps" "$floors" && ok "$name: host_steps.csv of stage 2 equal (1e-9)" \
    || bad "$name: host_steps.csv of stage 2 differs"
  local i1 i2
  i1=$(csv_awk -v f="$first" 'NR > 1 && $col("step") > f { printf "%s ", $col("iterations") }' "$d/one/steps.csv")
  i2=$(csv_awk 'NR > 1 && $col("step") > 0 { printf "%s ", $col("iterations") }' "$d/stage2/steps.csv")
  paste -d' ' <(echo "$i1" | tr ' ' '\n' | sed '/^$/d') <(echo "$i2" | tr ' ' '\n' | sed '/^$/d') |
    awk '{ d = $1 - $2; if (d < 0) d = -d; if (d > 2) bad = 1 } END { exit bad }' \
    && [ "$(echo "$i1" | wc -w)" = "$(echo "$i2" | wc -w)" ] \
    && ok "$name: iterations per step within 2 ([$i1] against [$i2])" || bad "$name: iterations [$i1] against [$i2]"
  diff <(sed -n '/^host:/,/^solver_state/{/^solver_state/!p}' "$d/one/state.yaml") \
       <(sed -n '/^host:/,/^solver_state/{/^solver_state/!p}' "$d/stage2/state.yaml") \
    >/dev/null && ok "$name: the host's values in state.yaml identical" || bad "$name: the host's values in state.yaml differ"
}

# 1. A confining pressure (stage 2 of 3: the relax, pressure steps in stage 1; the push in stage 2).
#    loading: 0 relax, 1 host_load left/right (the pressure), 2 host_load top (the push)
all=(); s1=(--delete loading.2); s2=(--delete loading.1 --delete loading.0)
restart_case pressure "$root/tests/hybrid/load_grains.yaml" 3
# 2. An infinite plane: host_load of 3 steps split into 2 and 1; tangential forces on particles.
#    loading: 0 relax, 1 host_load (3 steps of remote stress)
all=(--set 'materials.grain_boundary={kn: 1000, kt: 500, friction_deg: 20}')
s1=(--set loading.1.host_load.steps=2); s2=(--set loading.1.host_load.steps=1 --delete loading.0)
restart_case remote "$root/tests/hybrid/load_grains_remote.yaml" 3 ux:1e-4,uy:1e-4,fx:1,fy:1
csv_awk 'NR > 1 && $col("j") ~ /^p/ && $col("pt") != 0 { n++ } END { exit !(n > 0) }' "$out/remote/stage1/state_contacts.csv" \
  && ok "remote: the state carries tangential forces on boundary particles" || bad "remote: no tangential force on a particle"
# the scene's grains.max_overlap (0.7: the packing overlaps by up to 0.61) goes to its state, whose
# grains the restart admits with it
grep -q "^grains: {.*, max_overlap: 0.7}" "$out/remote/stage1/state.yaml" \
  && ok "remote: the state keeps the scene's max_overlap" || bad "remote: no max_overlap: 0.7 in the state"

# 3. States that do not fit. Each: a scene edit or a state edit, the expected message.
d=$out/pressure
refuse() { # label scene expected-message-regex
  rm -rf "$d/refused"
  msg=$("$gembem" run "$2" -o "$d/refused" 2>&1 >/dev/null); code=$?
  if [ $code -eq 2 ] && [[ $msg =~ $3 ]] && [ ! -e "$d/refused" ]; then ok "$1: refused: $msg"
  else bad "$1: exit $code, '$msg', expected /$3/"; fi
}
scene_edit "$d/s2.yaml" -o "$d/r_elements.yaml" --set host.elements.cavity=25
refuse "another mesh" "$d/r_elements.yaml" \
  "stage1/state.yaml:[0-9]+:[0-9]+: host.elements: the state's host has 44 elements, the scene's mesh .* has 45"
scene_edit "$d/s2.yaml" -o "$d/r_kind.yaml" --set 'host.boundary.left={traction: [0, 0]}'
refuse "another condition" "$d/r_kind.yaml" \
  "stage1/state.yaml:[0-9]+:[0-9]+: host.boundary.left: the state's condition is pressure, the scene's traction"
cp -r "$d/stage1" "$d/moved"; csv_awk 'NR == 3 { $col("x") = 1.5 } 1' OFS=, "$d/stage1/state_host.csv" > "$d/moved/state_host.csv"
scene_edit "$d/s2.yaml" -o "$d/r_moved.yaml" --set initial_state=moved/state.yaml
refuse "a particle off its element" "$d/r_moved.yaml" "moved/state_host.csv:3:[0-9]+: .*particle's centre on the element's midpoint"
cp -r "$d/stage1" "$d/nohost"; sed -i '/^host:/,/^solver_state/{/^solver_state/!d}' "$d/nohost/state.yaml"
scene_edit "$d/s2.yaml" -o "$d/r_nohost.yaml" --set initial_state=nohost/state.yaml
refuse "a state without a host" "$d/r_nohost.yaml" "nohost/state.yaml:[0-9]+:[0-9]+: the state has no host"
scene_edit "$d/s2.yaml" -o "$d/r_noscenehost.yaml" --delete host
refuse "a scene without a host" "$d/r_noscenehost.yaml" "stage1/state.yaml:[0-9]+:[0-9]+: host: the state comes from a run with a host"
scene_edit "$d/s1.yaml" -o "$d/followed.yaml" --add 'host.updated_lagrangian={every: 1}'
if "$gembem" run "$d/followed.yaml" -o "$d/followed" --quiet; then
  line=$(grep -n "^  followed: " "$d/followed/state.yaml" | cut -d: -f1)
  scene_edit "$d/s2.yaml" -o "$d/r_followed.yaml" --set initial_state=followed/state.yaml
  refuse "a state of a followed host" "$d/r_followed.yaml" "followed/state.yaml:$line:13: host.followed: the state's host followed its deformed boundary"
else bad "the followed host's stage 1 failed"; fi

# 4. A restart after the cavity has moved: stage 1's grains, particles and cavity displacements
#    moved down by 0.7 cm, more than a grain's radius (0.575 cm), so that the lowest grains lie
#    below the cavity at rest: accepted (each grain is checked against the cavity moved as the
#    state says; before, "lies outside the host's cavity"). The same state with one grain moved
#    5 cm to the right, into the host: refused.
cp -r "$d/stage1" "$d/down"
csv_awk 'BEGIN { OFS = ","; CONVFMT = "%.17g" } NR > 1 { $col("y") -= 0.7 } 1' "$d/stage1/state_grains.csv" > "$d/down/state_grains.csv"
csv_awk 'BEGIN { OFS = ","; CONVFMT = "%.17g" } NR > 1 { $col("y") -= 0.7; $col("uy") -= 0.7 } 1' "$d/stage1/state_host.csv" \
  > "$d/down/state_host.csv"
lowest=$(csv_awk 'NR > 1 && (m == "" || $col("y") - $col("r") < m) { m = $col("y") - $col("r") } END { print m }' \
  "$d/down/state_grains.csv")
bottom=$(csv_awk 'NR > 1 && (m == "" || $col("y") - $col("uy") < m) { m = $col("y") - $col("uy") } END { print m }' \
  "$d/down/state_host.csv")
scene_edit "$d/s2.yaml" -o "$d/r_down.yaml" --set initial_state=down/state.yaml --set solver.max_iterations=50
msg=$("$gembem" run "$d/r_down.yaml" -o "$d/down_run" --quiet 2>&1 >/dev/null); code=$?
if [ $code -ne 2 ] && ! grep -q "outside" <<< "$msg" && awk -v l="$lowest" -v b="$bottom" 'BEGIN { exit !(l < b) }'; then
  ok "moved cavity: a restart with grains below the cavity at rest (lowest edge $lowest, cavity's rest bottom $bottom) runs (exit $code)"
else
  bad "moved cavity: exit $code, '$msg' (lowest grain edge $lowest, cavity's rest bottom $bottom)"
fi
cp -r "$d/down" "$d/into_host"
csv_awk 'BEGIN { OFS = ","; CONVFMT = "%.17g" } NR == 2 { $col("x") += 5 } 1' "$d/down/state_grains.csv" > "$d/into_host/state_grains.csv"
scene_edit "$d/s2.yaml" -o "$d/r_into_host.yaml" --set initial_state=into_host/state.yaml
refuse "a grain in the host after the cavity moved" "$d/r_into_host.yaml" "into_host/state_grains.csv:2:[0-9]+: grain 0 .* has its centre outside the host's cavity"

gb_test_end
