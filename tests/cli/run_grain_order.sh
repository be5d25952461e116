#!/usr/bin/env bash
# The simulation keeps its grains in its own order (by cell, src/gem/sim.h) and numbers them as the
# scene does in everything it writes: one packing of 300 discs given in its order and reversed
# (grain i of the one is grain 299 - i of the other) is sheared with friction by both runs, whose
# files must then be the same up to that renumbering: the final grains (state_grains.csv), the
# contacts (state_contacts.csv, i < j, sorted by (i, j)), the sliding contacts and the per-grain
# measures (fields/), the stresses of every step. The two runs order their grains alike except
# where two discs share a cell, so they agree to rounding, not bit for bit (tolerance 1e-9
# relative: a renumbering error moves a grain by a diameter).
set -u
gembem=$(cd "$(dirname "$1")" && pwd)/$(basename "$1"); root=$(cd "$(dirname "$0")/../.." && pwd)
out=$(mktemp -d); fail=0
"$gembem" pack "$root/tests/pack/box_stress.yaml" -o "$out/pack" --quiet || { echo "FAIL: the packing"; exit 1; }
/usr/bin/python3 - "$out" <<'PY' || fail=1
import csv, os, re, sys
out = sys.argv[1]
rows = list(csv.reader(open(f"{out}/pack/state_grains.csv")))
head, grains = rows[0], rows[1:]
box = re.search(r"box: *\{[^}]*\}", open(f"{out}/pack/state.yaml").read()).group(0)
for name, order in (("given", grains), ("reversed", grains[::-1])):
    with open(f"{out}/{name}.csv", "w", newline="") as f:
        csv.writer(f).writerows([head] + order)
    with open(f"{out}/{name}.yaml", "w") as f:
        f.write(f"""gembem: 1
units: {{length: cm, force: dyn}}
materials:
  grain_grain: {{kn: 1.0e8, kt: 7.0e7, friction_deg: 25}}
  grain_wall:  {{kn: 1.0e8, kt: 7.0e7, friction_deg: 0}}
grains: {{file: {name}.csv}}
{box}
solver: {{accuracy: 100}}
loading:
  - strain: {{de1: 0.002, de2: -0.002, steps: 3}}
output: {{measures_every: 2}}
""")
PY
for name in given reversed; do
  (cd "$out" && "$gembem" run "$name.yaml" -o "$name" --quiet) || { echo "FAIL: the $name run"; fail=1; }
done
/usr/bin/python3 - "$out" <<'PY' || fail=1
import csv, glob, os, sys
out = sys.argv[1]
def table(path):
    return list(csv.DictReader(open(path)))
n = len(table(f"{out}/given/state_grains.csv"))
bad = []
def close(a, b, scale, what):
    a, b = float(a), float(b)
    if not abs(a - b) <= 1e-9 * scale:
        bad.append(f"{what}: {a!r} against {b!r}")
def renumber(rows, keys):
    """The reversed run's rows in the given run's numbering: grain k is n - 1 - k, each grain pair
    seen from its lower index (the normal changes sign, the tangential force does not)."""
    res = []
    for r in rows:
        r = dict(r)
        for k in keys:
            if r[k].lstrip("-").isdigit() and int(r[k]) >= 0: r[k] = str(n - 1 - int(r[k]))
        if r["j"].isdigit() and int(r["j"]) < int(r["i"]):
            r["i"], r["j"] = r["j"], r["i"]
            for c in ("nx", "ny", "xi", "yi", "xj", "yj", "mr"):
                if c in ("nx", "ny", "mr") and c in r: r[c] = str(-float(r[c]))
            if "xi" in r: r["xi"], r["xj"], r["yi"], r["yj"] = r["xj"], r["xi"], r["yj"], r["yi"]
        res.append(r)
    return sorted(res, key=lambda r: (int(r["i"]), r["j"]))
def same_contacts(a, b, what):
    a = sorted(a, key=lambda r: (int(r["i"]), r["j"]))
    b = renumber(b, ("i", "j"))
    if [(r["i"], r["j"]) for r in a] != [(r["i"], r["j"]) for r in b]:
        bad.append(f"{what}: other contacts ({len(a)} against {len(b)})")
        return
    for c in ("pn", "pt", "nx", "ny", "xi", "yi", "xj", "yj"):
        if not a or c not in a[0]: continue
        scale = max(abs(float(r[c])) for r in a) or 1
        for ra, rb in zip(a, b): close(ra[c], rb[c], scale, f"{what} ({ra['i']}, {ra['j']}) {c}")
# 1. grains
ga, gb = table(f"{out}/given/state_grains.csv"), table(f"{out}/reversed/state_grains.csv")[::-1]
for ra, rb in zip(ga, gb):
    for c in ("x", "y", "r", "rotation"): close(ra[c], rb[c], 10, f"state_grains {c}")
# 2. contacts of the final state; their order is the file's own (i, j)
ca = table(f"{out}/given/state_contacts.csv")
grain_pairs = [(int(r["i"]), int(r["j"])) for r in ca if r["j"].isdigit()]
if grain_pairs != sorted(grain_pairs) or any(i >= j for i, j in grain_pairs):
    bad.append("state_contacts.csv's grain pairs are not i < j sorted by (i, j)")
same_contacts(ca, table(f"{out}/reversed/state_contacts.csv"), "state_contacts")
# 3. every step's stresses
for ra, rb in zip(table(f"{out}/given/steps.csv"), table(f"{out}/reversed/steps.csv")):
    for c in ("s1", "s2"): close(ra[c], rb[c], abs(float(ra[c])) + 1, f"steps.csv step {ra['step']} {c}")
# 4. the measures' per-grain files and sliding contacts
sliding = []
files = sorted(os.path.basename(p) for p in glob.glob(f"{out}/given/fields/*"))
if not any(f.startswith("grains") for f in files): bad.append(f"no per-grain fields in {files}")
for f in files:
    if f.startswith("grains") and f.endswith(".csv"):
        fa, fb = table(f"{out}/given/fields/{f}"), table(f"{out}/reversed/fields/{f}")[::-1]
        for ra, rb in zip(fa, fb):
            for c in ("x0", "y0", "x", "y", "d2min"): close(ra[c], rb[c], 10, f"fields/{f} {c}")
    if f.startswith("sliding") and f.endswith(".csv"):
        sliding.append(len(table(f"{out}/given/fields/{f}")))
        same_contacts(table(f"{out}/given/fields/{f}"), table(f"{out}/reversed/fields/{f}"), f"fields/{f}")
print(f"{n} grains, {len(ca)} contacts, fields {files}, sliding {sliding}")
for b in bad[:10]: print("FAIL:", b)
sys.exit(1 if bad else 0)
PY
rm -rf "$out"
[ $fail -eq 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit $fail
