#!/usr/bin/python3
"""Runs the README's command blocks and compares what they print with the README (ctest docs_readme).

    /usr/bin/python3 tests/docs/readme_blocks.py README.md BUILD_DIR

The README's fenced blocks say by their info string what they are:

  ```sh            commands, run in order by bash (set -e) in a scratch copy of the repository's
                   layout (BUILD_DIR as build/, python/ and the sources read-only by symlink); the
                   working directory carries over from one block to the next, as a reader's would
  ```text          right after a sh block: what that block prints (stdout and stderr), line for line
  ```yaml NAME     a file the reader writes: saved as NAME in the current working directory
  ```python PATH   an excerpt of the repository's file PATH: every line must be in it, in order
  ```              (no info string) not run: tools/demo.sh and tools/test.sh install packages and
                   build; ctest demo_pipeline and the suite itself cover them

Printed text must equal the README's, except a number followed by " s" (a wall time): any number
is accepted there; and a slow step's progress lines ("gembem: step k (...) has run T s: ...",
printed only where a step runs long on a slow machine) are left out. Exits 1 with the first difference (block, line, expected and printed), else 0.
"""
import os
import re
import subprocess
import sys
import tempfile

FENCE = re.compile(r"^```(.*)$")
TIME = re.compile(r"\d+(?:\.\d+)? s\b")
SLOW_STEP = re.compile(r"^\r?gembem: step \d+ \(\d+ of \d+ in its stage\) has run ")


def blocks(path):
    """(line number, info string, text) of every fenced block of the Markdown file."""
    out, info, start, body = [], None, 0, []
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            m = FENCE.match(line.rstrip("\n"))
            if m and info is None:
                info, start, body = m.group(1).strip(), n, []
            elif m and info is not None:
                out.append((start, info, "".join(body)))
                info = None
            elif info is not None:
                body.append(line)
    return out


def same_line(expected, printed):
    """Equal, wall times aside."""
    return TIME.sub("T s", expected) == TIME.sub("T s", printed)


def compare(start, expected, printed):
    exp = expected.rstrip("\n").split("\n")
    got = [l for l in printed.rstrip("\n").split("\n") if not SLOW_STEP.match(l)]
    for k in range(max(len(exp), len(got))):
        e = exp[k] if k < len(exp) else "(no line)"
        g = got[k] if k < len(got) else "(no line)"
        if not same_line(e, g):
            return (f"README.md:{start + 1 + k}: the block prints another line than the README says\n"
                    f"  README:  {e}\n  printed: {g}")
    return None


def check_excerpt(repo, start, path, text):
    with open(os.path.join(repo, path), encoding="utf-8") as f:
        lines = [l.rstrip() for l in f]
    k = 0
    for want in text.rstrip("\n").split("\n"):
        while k < len(lines) and lines[k] != want.rstrip():
            k += 1
        if k == len(lines):
            return f"README.md:{start}: this line of the excerpt is not in {path} (in order): {want}"
        k += 1
    return None


def main():
    readme, build = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    repo = os.path.dirname(readme)
    found = blocks(readme)
    ran = 0
    with tempfile.TemporaryDirectory(prefix="gb_readme_") as root:
        for name in os.listdir(repo):   # the repository's layout, build/ being the build under test
            if name not in ("build", "runs", ".git"):
                os.symlink(os.path.join(repo, name), os.path.join(root, name))
        os.symlink(build, os.path.join(root, "build"))
        cwd = root
        for i, (start, info, text) in enumerate(found):
            kind, _, arg = info.partition(" ")
            if kind == "yaml" and arg:
                with open(os.path.join(cwd, arg.strip()), "w", encoding="utf-8") as f:
                    f.write(text)
            elif kind == "python" and arg:
                err = check_excerpt(repo, start, arg.strip(), text)
                if err:
                    print(err)
                    return 1
            elif kind == "sh":
                marker = os.path.join(root, ".cwd")
                script = f"set -e\n{text}\npwd > '{marker}'\n"
                env = dict(os.environ, OPENBLAS_NUM_THREADS=os.environ.get("OPENBLAS_NUM_THREADS", "1"))
                if os.environ.get("GB_SANITIZER_PRELOAD"):  # a sanitized build: python3 loads its library
                    env.update(LD_PRELOAD=os.environ["GB_SANITIZER_PRELOAD"], ASAN_OPTIONS="detect_leaks=0")
                r = subprocess.run(["bash", "-c", script], cwd=cwd, env=env, text=True,
                                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
                if r.returncode != 0:
                    print(f"README.md:{start}: the block exits with status {r.returncode}:\n{text}{r.stdout}")
                    return 1
                with open(marker, encoding="utf-8") as f:
                    cwd = f.read().strip()
                ran += 1
                nxt = found[i + 1] if i + 1 < len(found) else None
                if nxt and nxt[1] == "text":
                    err = compare(nxt[0], nxt[2], r.stdout)
                    if err:
                        print(err)
                        return 1
    if ran == 0:
        print("README.md: no ```sh block found: the README's commands are not checked")
        return 1
    print(f"README.md: {ran} command blocks run, their printed lines as the README says")
    return 0


if __name__ == "__main__":
    sys.exit(main())
