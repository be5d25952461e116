#!/usr/bin/python3
"""Include cycles between the folders of src/: ctest tools_include_cycles.

Builds the graph of src/'s folders: an edge A -> B when a file of src/A/ has `#include "B/..."`
and B is another folder of src/ (the public headers, include/gembem/, are no folder of src/).
Prints every elementary cycle of that graph with the files that make each edge, and exits 1 if
there is one. Exit 2 on bad usage.

Usage: check_include_cycles.py [SRC_DIR]
  SRC_DIR       default: the src/ next to this tools/ folder
"""
import os
import re
import sys

# The layers, each including only folders before it: core, contact, hybrid, bem, scene, gem,
# solver, measure, io, run, pack, cli (docs/developers.md). A new cycle means a file is in the
# wrong folder.

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
    if len(argv) > 1 or any(a.startswith("--") for a in argv):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    src = argv[0] if argv else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "src")
    if not os.path.isdir(src):
        print(f"check_include_cycles: {src}: not a directory", file=sys.stderr)
        return 2
    graph = folder_graph(src)
    found = cycles(graph)
    for c in found:
        print("CYCLE " + show(c, graph))
    print(f"{len(found)} cycles between the folders of {os.path.normpath(src)}")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
