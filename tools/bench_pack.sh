#!/usr/bin/env bash
# The scale of `gembem pack` (not a test): N discs of the paper's three diameters (0.6, 0.9, 1.2 cm,
# equal area each; validation/packing/box_growth.yaml's scene) grown in a square box until their
# mean stress is 1e-4 kn (just past jamming), frictionless, then Kishino's friction switched on.
# The box holds the grains at solid fraction 0.84 (radius_scale near 1). Prints a Markdown row per
# N: wall seconds per phase (pack_info.yaml) and the process's CPU seconds (user + system, the
# measure that a loaded machine spoils least), FIRE iterations per phase, CPU microseconds per
# iteration (CPU seconds over FIRE iterations), peak resident memory (/usr/bin/time -v), porosity,
# coordination (without rattlers), mean stress and the largest fixing force. Runs in runs/bench_pack/nN (kept: state.yaml is a
# packing that run scenes start from).
#   tools/bench_pack.sh [BUILD_DIR] [N ...]      (N: 10000 100000 by default)
# STRESS=s grows to s dyn/cm instead, in runs/bench_pack/nN_sS (tools/bench_peer.sh's PATH_START:
# STRESS=1.0e5 THREADS=2 tools/bench_pack.sh build 100000 is the start of its 1e5 path rows).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/${1:-build}; shift || true
sizes=${*:-10000 100000}
# THREADS=n (default 1) puts `threads: n` in the scene's solver section: FIRE then runs on n OpenMP
# threads (the packing is the same bits whatever their number); on a machine other jobs load,
# OMP_WAIT_POLICY=passive keeps a waiting thread from spinning on the core the others need.
threads=${THREADS:-1}
stress=${STRESS:-} # another target stress than box_growth.yaml's 1.0e4 dyn/cm (its own directories)
# SOLID_FRACTION=phi grows to that solid fraction instead of a stress, in runs/bench_pack/nN_phiPHI (the
# column "mean stress / target" is then the mean stress reached, in dyn/cm)
solid=${SOLID_FRACTION:-}
# FRICTION_DEG=f packs with the grains' friction angle f (pack.friction_deg, at most the scene's 25)
# instead of frictionless, in runs/bench_pack/nN_fF: the porosity then rises with f (docs/packing.md);
# the scene's solver is then the global one (method: global), which finishes FIRE's settling from
# 4 times the accuracy in a growth to a stress (src/pack/pack.c's SETTLE_FINISHED)
friction=${FRICTION_DEG:-}
echo "machine: $(nproc --all) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); $(date -u '+%Y-%m-%d %H:%M'); load average $(cut -d' ' -f1-3 /proc/loadavg); threads $threads, OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-unset}${friction:+, friction while packing $friction deg}"
echo
echo "| discs | seconds: total [CPU] (place / grow / settle / equilibrium) | FIRE iterations: grow + settle | CPU us per iteration | peak memory [MB] | porosity | coordination (without rattlers) | rattlers | mean stress / target | largest fixing force / accuracy |"
echo "|---:|---|---|---:|---:|---:|---|---:|---:|---:|"
for n in $sizes; do
  d=$root/runs/bench_pack/n$n${stress:+_s$stress}${solid:+_phi$solid}${friction:+_f$friction}
  mkdir -p "$d"
  # the mean disc area of the mix: 1 / sum over sizes of (1/3) / (pi r^2)
  side=$(awk -v n="$n" 'BEGIN { pi = atan2(0, -1); s = 0; split("0.3 0.45 0.6", r, " ");
                                for (k = 1; k <= 3; k++) s += 1 / (3 * pi * r[k] * r[k]);
                                printf "%.6g", sqrt(n / s / 0.84) }')
  sed -e "s/right: 24.4/right: $side/; s/top: 24.4/top: $side/; s/count: 1000$/count: $n/" \
      -e "s/^solver: {/solver: {${friction:+method: global, }threads: $threads, /" ${stress:+-e "s/stress: 1.0e4\$/stress: $stress/"} \
      ${solid:+-e "s/stress: 1.0e4\$/solid_fraction: $solid/"} \
      ${friction:+-e "s/^pack:\$/pack:\n  friction_deg: $friction/"} \
    "$root/validation/packing/box_growth.yaml" > "$d/scene.yaml"
  grep -q "count: $n$" "$d/scene.yaml" && { [ -z "$friction" ] || grep -q "friction_deg: $friction$" "$d/scene.yaml"; } &&
    { [ -z "$solid" ] || grep -q "solid_fraction: $solid$" "$d/scene.yaml"; } || { echo "bench_pack.sh: could not make the scene for $n discs" >&2; exit 1; }
  /usr/bin/time -v "$build/gembem" pack "$d/scene.yaml" -o "$d/out" --overwrite --quiet 2> "$d/time.log" ||
    { cat "$d/time.log" >&2; exit 1; }
  mb=$(awk '/Maximum resident set size/ { printf "%.0f", $NF / 1024 }' "$d/time.log")
  cpu=$(awk -F': ' '/User time|System time/ { s += $2 } END { printf "%.1f", s }' "$d/time.log")
  /usr/bin/python3 - "$d/out/pack_info.yaml" "$n" "$mb" "$cpu" <<'PY'
import re, sys
info = {}
for line in open(sys.argv[1]):
    if ":" in line and not line.startswith("#"):
        k, v = line.split(":", 1)
        info[k.strip()] = v.split("#")[0].strip()
def braces(v):
    return {a.strip(): float(b) for a, b in (x.split(":") for x in v.strip("{}").split(","))}
sec, it = braces(info["seconds"]), braces(info["fire_iterations"])
its = it["grow"] + it["settle"]
m = re.search(r"stress: ([0-9.e+-]+)", info["target"])
target = float(m.group(1)) if m else 1.0  # a solid fraction: the stress itself
print(f"| {sys.argv[2]} | {sec['total']:.1f} [{sys.argv[4]}] ({sec['place']:.2f} / {sec['grow']:.1f} / {sec['settle']:.1f} / "
      f"{sec['equilibrium']:.2f}) | {it['grow']:.0f} + {it['settle']:.0f} | {1e6 * float(sys.argv[4]) / its:.0f} | {sys.argv[3]} | "
      f"{float(info['porosity']):.4f} | {float(info['coordination']):.3f} "
      f"({float(info['coordination_without_rattlers']):.3f}) | {info['rattlers']} | "
      f"{float(info['mean_stress']) / target:{'.4f' if m else '.4g'}} | {float(info['max_fixing_force']):.3g} / {info['accuracy']} |")
PY
done
