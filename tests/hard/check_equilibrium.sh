#!/usr/bin/env bash
# Issue 25, item 4: a converged state is a frictional equilibrium by docs/method.md's law, checked by an
# independent recomputation (tools/check_equilibrium.py: its own contact detection, pn = kn d from
# the positions, the stored pt, every grain's force and moment) after an oedometric path from the
# jammed fixture with each solver (reference, global, global with newton: line_search); and the
# checker fails on a state that is not one (a grain moved by 1e-5 cm; a tangential force past its
# Coulomb cap). The same runs check solver.history's history.csv against steps.csv, and steps.csv's
# error columns of the last step against tools/check_step_error.py's recomputation.
#   check_equilibrium.sh GEMBEM JAMMED_DIR OUT_DIR
set -euo pipefail
gembem=$1 jammed=$2 out=$3
source "$(dirname "$0")/path_scene.sh"
source "$(dirname "$0")/../csv.sh"
rm -rf "$out"; mkdir -p "$out"
for method in reference global line_search; do
  path_scene $method "$jammed" "$out/$method.yaml" --add solver.history=true --add 'output={contacts_every: 1}'
  OPENBLAS_NUM_THREADS=1 "$gembem" run "$out/$method.yaml" -o "$out/$method" --quiet > /dev/null
  if /usr/bin/python3 "$check" "$out/$method"; then ok "$method: the final state is an equilibrium"
  else bad "$method: the final state is not an equilibrium"; fi
  # steps.csv's error columns of the last step, recomputed from the state
  if /usr/bin/python3 "$steperr" "$out/$method"; then ok "$method: steps.csv's error columns recomputed"
  else bad "$method: steps.csv's error columns differ from the state's"; fi
  # solver.history: one row per iteration that did not converge, the iterations of steps.csv, each
  # starting above the accuracy, the line search's length in (0, 1]; each step's smoother steps
  # summed over its iterations' rows are steps.csv's; the smoother's progress rows (smoother 1)
  # are one per 1 000 of an iteration's steps.
  if csv_awk -v m=$method 'FNR == 1 { next }
      FILENAME ~ /steps/ { its += $col("iterations"); sweeps[$col("step")] = $col("sweeps"); next }
      $col("smoother") == 1 { progress[$col("step") "," $col("attempt") "," $col("iteration")]++; next }
      { key = $col("step") "," $col("attempt") "," $col("iteration"); summed[$col("step")] += $col("sweeps");
        if (progress[key] + 0 != int($col("sweeps") / 1000)) bad = "iteration " key ": " progress[key] + 0 " progress rows for " $col("sweeps") " smoother steps" }
      { rows++; if ($col("max_fixing_force") <= 100) bad = "a row at or below the accuracy";
        if (m == "line_search" && !($col("length") >= 0 && $col("length") <= 1)) bad = "a length outside [0, 1]";
        if (m == "reference" && ($col("damping") != 0 || $col("length") != 0))
          bad = "damping or length for the reference iteration" }
      END { if (rows != its) bad = rows " rows for " its " iterations";
            for (k in sweeps) if (k > 0 && summed[k] + 0 != sweeps[k]) bad = "step " k ": " summed[k] + 0 " smoother steps in history.csv, " sweeps[k] " in steps.csv";
            if (bad) { print bad; exit 1 } }' \
      "$out/$method/steps.csv" "$out/$method/history.csv"; then ok "$method: history.csv has a row per iteration"
  else bad "$method: history.csv"; fi
done
# Negative controls: the checker must refuse these.
cp -r "$out/global" "$out/moved"
csv_awk 'NR == 2 { $col("x") = sprintf("%.17g", $col("x") + 1e-5) } 1' OFS=, "$out/global/state_grains.csv" > "$out/moved/state_grains.csv"
if /usr/bin/python3 "$check" "$out/moved" > "$out/moved.log"; then bad "a grain moved by 1e-5 cm passed"
else ok "a grain moved by 1e-5 cm fails: $(grep -c FAIL "$out/moved.log") reasons"; fi
cp -r "$out/global" "$out/slip"
csv_awk 'NR > 1 && $col("j") ~ /^[0-9]+$/ && !done { $col("pt") = sprintf("%.17g", 0.47 * $col("pn")); done = 1 } 1' OFS=, \
  "$out/global/state_contacts.csv" > "$out/slip/state_contacts.csv"
if /usr/bin/python3 "$check" "$out/slip" > "$out/slip.log" || ! grep -q Coulomb "$out/slip.log"; then
  bad "a tangential force of 0.47 pn (tan 25 deg = 0.466) passed"
else ok "a tangential force past its Coulomb cap fails"; fi
if /usr/bin/python3 "$steperr" "$out/slip" > "$out/slip_steps.log" || ! grep -q "FAIL.*coulomb_excess" "$out/slip_steps.log"; then
  bad "check_step_error.py did not see the Coulomb excess of 0.47 pn against steps.csv's"
else ok "check_step_error.py finds the tangential force past its cap"; fi
[ $fails = 0 ] || { echo "$fails failure(s)"; exit 1; }
