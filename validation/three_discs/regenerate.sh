#!/usr/bin/env bash
# Regenerates validation/three_discs/README.md's table and fig7.png from fresh runs.
#   validation/three_discs/regenerate.sh [BUILD_DIR]     (default: build)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd); root=$(cd "$here/../.." && pwd)
gembem=$root/${1:-build}/gembem
runs=$root/runs/three_discs
mkdir -p "$runs"
for s in case1 case2 case3 case4 friction_wall0 friction_wall5 friction_wall10 friction_wall15; do
  "$gembem" run "$here/$s.yaml" -o "$runs/$s" --overwrite --quiet
done
table=$(cd "$here" && /usr/bin/python3 table2.py "$runs/case1" "$runs/case2" "$runs/case3" "$runs/case4")
(cd "$here" && /usr/bin/python3 fig7.py "$here/fig7.png" "$runs"/friction_wall{0,5,10,15})
# Replace the text between the markers in README.md.
/usr/bin/python3 - "$here/README.md" "$table" <<'PY'
import sys
path, table = sys.argv[1], sys.argv[2]
text = open(path).read()
a, b = "<!-- table2:begin -->", "<!-- table2:end -->"
i, j = text.index(a) + len(a), text.index(b)
open(path, "w").write(text[:i] + "\n" + table + "\n" + text[j:])
PY
echo "$table"
echo "wrote $here/fig7.png and the table in $here/README.md"
