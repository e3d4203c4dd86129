#!/usr/bin/python3
"""Checks that every relative link in README.md and docs/*.md resolves, anchors included.

    /usr/bin/python3 scripts/check_doc_links.py [FILE.md ...]

A link [text](target) outside code blocks and code spans is checked when it is relative (no
scheme): the file or folder must exist, relative to the linking file, and a #anchor must name a
heading of the target file, slugged as GitHub does (lowercase; characters other than letters,
digits, spaces, '-' and '_' dropped; spaces to '-'; a repeated slug gets -1, -2, ...).
Also refused: a link that leaves the repository. Prints one line per broken link
(FILE:LINE: target: why) and exits 1 if there is any, 0 otherwise. Works from any directory.
"""

import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
LINK = re.compile(r"(?<!\!)\[(?:[^\]\[]|\[[^\]]*\])*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
IMAGE = re.compile(r"!\[[^\]]*\]\(([^)\s]+)\)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
FENCE = re.compile(r"^\s*(```|~~~)")


def prose_lines(text):
    """(line number, line) outside fenced code blocks, with inline code spans blanked."""
    fenced = False
    for number, line in enumerate(text.splitlines(), start=1):
        if FENCE.match(line):
            fenced = not fenced
            continue
        if not fenced:
            yield number, re.sub(r"`[^`]*`", "``", line)


def slug(heading):
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link's text only
    text = text.replace("`", "").lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def heading_anchors(path):
    """Anchors of the headings of a file, code spans' text included."""
    seen = {}
    names = set()
    fenced = False
    for line in path.read_text(encoding="utf-8").splitlines():
        if FENCE.match(line):
            fenced = not fenced
            continue
        m = None if fenced else HEADING.match(line)
        if not m:
            continue
        base = slug(m.group(2))
        count = seen.get(base, 0)
        names.add(base if count == 0 else f"{base}-{count}")
        seen[base] = count + 1
    return names


def check(md):
    problems = []
    text = md.read_text(encoding="utf-8")
    for number, line in prose_lines(text):
        for m in list(LINK.finditer(line)) + list(IMAGE.finditer(line)):
            target = m.group(1)
            if re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", target):
                continue  # https:, mailto: ...
            where = f"{md.relative_to(ROOT)}:{number}: {target}"
            path_part, _, anchor = target.partition("#")
            dest = (md.parent / path_part).resolve() if path_part else md
            try:
                dest.relative_to(ROOT)
            except ValueError:
                problems.append(f"{where}: leaves the repository")
                continue
            if not dest.exists():
                problems.append(f"{where}: no such file or folder")
                continue
            if anchor:
                if dest.is_dir() or dest.suffix != ".md":
                    problems.append(f"{where}: an anchor into a file that is not Markdown")
                elif anchor not in heading_anchors(dest):
                    problems.append(f"{where}: no heading with this anchor in {dest.name}")
    return problems


def main(argv):
    files = [Path(a).resolve() for a in argv] or [ROOT / "README.md",
                                                  *sorted((ROOT / "docs").glob("*.md"))]
    problems = [p for md in files for p in check(md)]
    for p in problems:
        print(p)
    if problems:
        print(f"check_doc_links: {len(problems)} broken link(s)", file=sys.stderr)
        return 1
    print(f"check_doc_links: {len(files)} files, every relative link resolves", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
