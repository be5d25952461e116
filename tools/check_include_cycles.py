#!/usr/bin/python3
"""Include cycles between the folders of src/: ctest tools_include_cycles.

Builds the graph of src/'s folders (the modules): an edge A -> B when a file of src/A/ has
`#include "B/..."` for another folder B of src/, or `#include "gembem/x.h"` for a public header
that module B implements. The module of a public header is derived from the code: the folder of
src/ whose .c files define the functions it declares. A public header that declares no function
defined in src/ (types, static inline functions, the umbrella gembem.h) belongs to no module: an
include of it stands for the includes it has. A public header's own includes of other public
headers are edges of its module.

Prints every elementary cycle of that graph with the files that make each edge, every public
header whose functions are defined in more than one folder (one public header per module), and,
in a tree of gembem's layers (LAYERS), every edge that points up the layers and every folder not
placed in them; exits 1 if there is any. Exit 2 on bad usage.

Usage: check_include_cycles.py [SRC_DIR [INCLUDE_DIR]]
  SRC_DIR       default: the src/ next to this tools/ folder
  INCLUDE_DIR   the folder holding gembem/ (the public headers); default: SRC_DIR/../include
"""
import os
import re
import sys

# The layers, lowest first, each including only folders before it (docs/architecture.md,
# docs/developers.md). A cycle or an edge upwards means a file, a declaration or a type is in the
# wrong folder; a new folder takes its place in this list.
LAYERS = ("core", "bem", "contact", "scene", "hybrid", "gem", "solver", "measure", "io", "run", "pack", "cli")

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"/]+)/([^"]+)"')
PUBLIC = "gembem"
IDENT = re.compile(r"[A-Za-z_]\w*")


def code_only(text):
    """The C text without comments, string and character literals and preprocessor lines."""
    text = re.sub(r'/\*.*?\*/|//[^\n]*|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'',
                  lambda m: " " if m.group(0)[0] == "/" else '""', text, flags=re.S)
    return re.sub(r"^\s*#(?:[^\n]*\\\n)*[^\n]*", "", text, flags=re.M)


def top_level(text):
    """The file-scope pieces of C text, each as (text before its end, end): end is ';' for a
    declaration and '{' for a definition (the body skipped)."""
    pieces, start, depth, paren, i = [], 0, 0, 0, 0
    while i < len(text):
        c = text[i]
        if c == "(":
            paren += 1
        elif c == ")":
            paren -= 1
        elif c == "{":
            if depth == 0 and paren == 0:
                pieces.append((text[start:i], "{"))
            depth += 1
        elif c == "}":
            depth -= 1
            if depth == 0 and paren == 0:
                start = i + 1
        elif c == ";" and depth == 0 and paren == 0:
            pieces.append((text[start:i], ";"))
            start = i + 1
        i += 1
    return pieces


def function_name(piece):
    """The function a file-scope piece declares or defines, or None (a type, a variable, a
    function pointer, a static function)."""
    head = piece.split("(", 1)[0]
    words = IDENT.findall(head)
    if "(" not in piece or "=" in head or not words or "typedef" in words or "static" in words:
        return None
    if re.match(r"\(\s*\*", piece[len(head):]):
        return None
    return words[-1]


def read(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        return f.read()


def definitions(src, folders):
    """{function: {folder: file}} of the functions the .c files of src's folders define."""
    found = {}
    for a in folders:
        for root, _, files in os.walk(os.path.join(src, a)):
            for name in sorted(files):
                if name.endswith(".c"):
                    path = os.path.join(root, name)
                    for piece, end in top_level(code_only(read(path))):
                        fn = function_name(piece) if end == "{" else None
                        if fn:
                            found.setdefault(fn, {}).setdefault(a, os.path.relpath(path, src))
    return found


def includes(path):
    """[(folder, rest)] of the file's `#include "folder/rest"` lines."""
    out = []
    for line in read(path).splitlines():
        m = INCLUDE.match(line)
        if m:
            out.append((m.group(1), m.group(2)))
    return out


def public_modules(incdir, defs):
    """({header: {folder: [functions]}}, {header: [public headers it includes]}) for the headers
    of incdir/gembem: where the functions each declares are defined, and its includes."""
    where, uses = {}, {}
    pub = os.path.join(incdir, PUBLIC) if incdir else None
    if not pub or not os.path.isdir(pub):
        return where, uses
    for name in sorted(os.listdir(pub)):
        if not name.endswith(".h"):
            continue
        path = os.path.join(pub, name)
        folders = {}
        for piece, end in top_level(code_only(read(path))):
            fn = function_name(piece) if end == ";" else None
            for folder in sorted(defs.get(fn, {})) if fn else ():
                folders.setdefault(folder, []).append(fn)
        where[name] = folders
        uses[name] = [rest for folder, rest in includes(path) if folder == PUBLIC and rest != name]
    return where, uses


def resolve(header, where, uses, seen=None):
    """The modules an include of a public header makes an edge to: its own module, or, for a
    header of none, those of the public headers it includes."""
    if header not in where:
        return set()
    if where[header]:
        return set(where[header])
    seen = (seen or set()) | {header}
    return set().union(*[resolve(h, where, uses, seen) for h in uses[header] if h not in seen])


def folder_graph(src, incdir=None):
    """({A: {B: [files that make the edge A -> B]}}, {header: {folder: [functions]}})."""
    folders = sorted(d for d in os.listdir(src) if os.path.isdir(os.path.join(src, d)))
    defs = definitions(src, folders)
    where, uses = public_modules(incdir, defs)
    graph = {f: {} for f in folders}

    def edge(a, b, rel):
        if b in graph and b != a:
            users = graph[a].setdefault(b, [])
            if rel not in users:
                users.append(rel)

    def targets(folder, rest):
        return resolve(rest, where, uses) if folder == PUBLIC else {folder}

    for a in folders:
        for root, _, files in os.walk(os.path.join(src, a)):
            for name in sorted(files):
                if name.endswith((".c", ".h")):
                    path = os.path.join(root, name)
                    for folder, rest in includes(path):
                        for b in sorted(targets(folder, rest)):
                            edge(a, b, os.path.relpath(path, src))
    for header, mods in where.items():
        for a in mods:
            for used in uses[header]:
                for b in sorted(resolve(used, where, uses)):
                    edge(a, b, f"{PUBLIC}/{header}")
    return graph, where


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


def misplaced(graph):
    """The edges that point up the layers, [(a, b)], and the folders not in LAYERS, for a tree of
    gembem's layers (one of its folders is in LAYERS); nothing for another tree."""
    if not any(f in LAYERS for f in graph):
        return [], []
    up = [(a, b) for a in sorted(graph) for b in sorted(graph[a])
          if a in LAYERS and b in LAYERS and LAYERS.index(b) > LAYERS.index(a)]
    return up, sorted(f for f in graph if f not in LAYERS)


def show(cycle, graph):
    ring = list(cycle) + [cycle[0]]
    lines = [" -> ".join(ring)]
    for a, b in zip(ring, ring[1:]):
        users = graph[a][b]
        more = f" and {len(users) - 2} more" if len(users) > 2 else ""
        lines.append(f"    {a} -> {b}: {', '.join(users[:2])}{more}")
    return "\n".join(lines)


def main(argv):
    if len(argv) > 2 or any(a.startswith("--") for a in argv):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    src = argv[0] if argv else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "src")
    incdir = argv[1] if len(argv) > 1 else os.path.join(src, "..", "include")
    for d in [src] + argv[1:]:
        if not os.path.isdir(d):
            print(f"check_include_cycles: {d}: not a directory", file=sys.stderr)
            return 2
    graph, where = folder_graph(src, incdir)
    split = {h: mods for h, mods in sorted(where.items()) if len(mods) > 1}
    for h, mods in split.items():
        parts = "; ".join(f"{m}: {', '.join(fns)}" for m, fns in sorted(mods.items()))
        print(f"SPLIT {PUBLIC}/{h}: its functions are defined in {len(mods)} folders ({parts})")
    found = cycles(graph)
    for c in found:
        print("CYCLE " + show(c, graph))
    up, unplaced = misplaced(graph)
    for a, b in up:
        print(f"UPWARD {a} -> {b}: {', '.join(graph[a][b])} ({b} is above {a} in the layers)")
    for f in unplaced:
        print(f"UNPLACED {f}: a folder of src/ not in the layers (LAYERS, docs/architecture.md)")
    for h, mods in sorted(where.items()):
        print(f"module of {PUBLIC}/{h}: {', '.join(sorted(mods)) or 'none (no functions of its own)'}")
    print(f"{len(found)} cycles between the folders of {os.path.normpath(src)}, "
          f"{len(split)} public headers implemented in several folders")
    return 1 if found or split or up or unplaced else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
