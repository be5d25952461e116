#!/usr/bin/python3
"""Checks the relative links of README.md and docs/*.md (ctest tools_docs_links).

    /usr/bin/python3 tools/check_docs_links.py [REPO_ROOT]

Every Markdown link or image `[text](target)` whose target is not a URL must name a file or
directory of the repository (relative to the page), and an anchor `#section` (alone or after a
.md page) must be one of that page's headings, slugged as GitHub does. Prints each broken link as
`page:line: target: why` and exits 1 if there is any, else prints the count checked and exits 0.
"""
import os
import re
import sys

LINK = re.compile(r"!?\[(?:[^\]\[]|\[[^\]]*\])*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")


def slug(heading):
    """GitHub's anchor for a heading: lower case, punctuation but '-' and '_' dropped, spaces to '-'."""
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link in a heading keeps its text
    text = text.strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(path):
    seen, out, fence = {}, set(), False
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.lstrip().startswith("```"):
                fence = not fence
                continue
            m = None if fence else HEADING.match(line)
            if not m:
                continue
            s = slug(m.group(2))
            n = seen.get(s, 0)
            seen[s] = n + 1
            out.add(s if n == 0 else f"{s}-{n}")
    return out


def pages(root):
    yield os.path.join(root, "README.md")
    docs = os.path.join(root, "docs")
    for dirpath, _, files in os.walk(docs):
        for name in sorted(files):
            if name.endswith(".md"):
                yield os.path.join(dirpath, name)


def main(argv):
    root = os.path.abspath(argv[1] if len(argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    bad, checked = [], 0
    for page in pages(root):
        fence = False
        with open(page, encoding="utf-8") as f:
            lines = f.readlines()
        for no, line in enumerate(lines, 1):
            if line.lstrip().startswith("```"):
                fence = not fence
                continue
            if fence:
                continue
            for m in LINK.finditer(re.sub(r"`[^`]*`", "", line)):
                target = m.group(1)
                if re.match(r"^[a-z][a-z0-9+.-]*:", target):  # http:, https:, mailto:
                    continue
                checked += 1
                path, _, anchor = target.partition("#")
                dest = os.path.normpath(os.path.join(os.path.dirname(page), path)) if path else page
                where = f"{os.path.relpath(page, root)}:{no}: {target}"
                if not os.path.exists(dest):
                    bad.append(f"{where}: no such file")
                elif not os.path.realpath(dest).startswith(os.path.realpath(root) + os.sep) and dest != root:
                    bad.append(f"{where}: outside the repository")
                elif anchor and dest.endswith(".md") and anchor not in anchors(dest):
                    bad.append(f"{where}: no heading with this anchor in {os.path.relpath(dest, root)}")
    for b in bad:
        print(b)
    print(f"{checked} relative links checked, {len(bad)} broken")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
