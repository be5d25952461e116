#!/usr/bin/python3
"""Include cycles between the folders of src/ (issue 18, item 1): ctest tools_include_cycles.

Builds the graph of src/'s folders: an edge A -> B when a file of src/A/ has `#include "B/..."`
and B is another folder of src/ (the public headers, include/gembem/, are no folder of src/).
Prints every elementary cycle of that graph (a new one with the files that make each edge), exits 1
when a cycle is not in ALLOWED below, or when an ALLOWED cycle is gone (then delete it from the
list: a cycle removed must not come back unnoticed). Exit 2 on bad usage.

Usage: check_include_cycles.py [SRC_DIR] [--no-allowed]
  SRC_DIR       default: the src/ next to this tools/ folder
  --no-allowed  check against an empty allow-list (the self-test's fake trees)
"""
import os
import re
import sys

# Today's cycles (2026-11-24, HEAD of main b28a03f), each from its alphabetically first folder.
# Issue 18 removes them: delete an entry when its cycle is gone; never add one. The edges:
#   bem -> scene      bem/scene.c, bem/scene_read.h: the BEM module's own YAML scene reader
#   scene -> bem      scene/host_read.c, scene/state_read.c: the host section read by bem/scene_read.h
#   gem -> global     gem/sim.h: gb_sim holds the global solver's state
#   global -> gem     global/global_impl.h: the solver works on gb_sim
#   gem -> hybrid     gem/sim.h: gb_sim holds the host
#   hybrid -> gem     hybrid/host_output.c: the host's outputs read gb_sim
#   gem -> scene      gem/program.c: the loading program admits grains (scene/admit.h)
#   hybrid -> io      hybrid/host_output.c: io/file_util.h
#   io -> hybrid      io/run_output.c: the host's outputs
#   io -> gem         io/checkpoint.c, run_output.c, run_record.c, state_write.c: gb_sim's fields
#   io -> measure     io/run_output.c: the run output calls the per-step measures
#   measure -> io     measure/measure_output.c: io/file_util.h
#   measure -> gem    measure/host_measure.c, measure_output.c, micro.c, sliding.c: gb_sim's fields
#   io -> scene       io/state_write.c: scene/grains_file.h
#   scene -> io       scene/grains_file.c, scene/state_read.c: io/csv_read.h
#   hybrid -> bem     hybrid/host_output.c: bem/output.h
ALLOWED = [
    # two folders (issue 18 names five; io <-> scene is the sixth)
    ("bem", "scene"),
    ("gem", "global"),
    ("gem", "hybrid"),
    ("hybrid", "io"),
    ("io", "measure"),
    ("io", "scene"),
    # longer: through io -> gem, measure -> gem and gem -> scene
    ("bem", "scene", "io", "gem", "hybrid"),
    ("bem", "scene", "io", "hybrid"),
    ("bem", "scene", "io", "measure", "gem", "hybrid"),
    ("gem", "hybrid", "io"),
    ("gem", "hybrid", "io", "measure"),
    ("gem", "scene", "io"),
    ("gem", "scene", "io", "hybrid"),
    ("gem", "scene", "io", "measure"),
]

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"/]+)/')


def folder_graph(src):
    """{A: {B: [files of A that include B/...]}} over the folders of src."""
    folders = sorted(d for d in os.listdir(src) if os.path.isdir(os.path.join(src, d)))
    graph = {f: {} for f in folders}
    for a in folders:
        for root, _, files in os.walk(os.path.join(src, a)):
            for name in sorted(files):
                if not name.endswith((".c", ".h")):
                    continue
                path = os.path.join(root, name)
                with open(path, encoding="utf-8", errors="replace") as f:
                    for line in f:
                        m = INCLUDE.match(line)
                        if m and m.group(1) in graph and m.group(1) != a:
                            users = graph[a].setdefault(m.group(1), [])
                            rel = os.path.relpath(path, src)
                            if rel not in users:
                                users.append(rel)
    return graph


def cycles(graph):
    """Every elementary cycle, once, as a tuple starting at its alphabetically first folder."""
    found = []

    def walk(start, node, path):
        for nxt in sorted(graph[node]):
            if nxt == start:
                found.append(tuple(path))
            elif nxt > start and nxt not in path:
                walk(start, nxt, path + [nxt])

    for start in sorted(graph):
        walk(start, start, [start])
    return found


def show(cycle, graph):
    ring = list(cycle) + [cycle[0]]
    lines = [" -> ".join(ring)]
    for a, b in zip(ring, ring[1:]):
        users = graph[a][b]
        more = f" and {len(users) - 2} more" if len(users) > 2 else ""
        lines.append(f"    {a} -> {b}: {', '.join(users[:2])}{more}")
    return "\n".join(lines)


def main(argv):
    args = [a for a in argv if not a.startswith("--")]
    opts = [a for a in argv if a.startswith("--")]
    if len(args) > 1 or any(o != "--no-allowed" for o in opts):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    src = args[0] if args else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "src")
    if not os.path.isdir(src):
        print(f"check_include_cycles: {src}: not a directory", file=sys.stderr)
        return 2
    allowed = set() if "--no-allowed" in opts else set(ALLOWED)
    graph = folder_graph(src)
    found = cycles(graph)
    new = [c for c in found if c not in allowed]
    gone = sorted(allowed - set(found))
    for c in found:
        print("NEW CYCLE " + show(c, graph) if c in new else "allowed   " + " -> ".join(c + (c[0],)))
    for c in gone:
        print(f"GONE      {' -> '.join(c + (c[0],))}: no longer a cycle; delete it from ALLOWED in {__file__}")
    print(f"{len(found)} cycles between the folders of {os.path.normpath(src)}: {len(new)} not allowed, "
          f"{len(gone)} allowed ones gone")
    return 1 if new or gone else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
