#!/usr/bin/env python3
"""Lists the longest functions of the product code (not tests, bench or reference oracles).

    python3 scripts/function_lengths.py [--over N] [--top K] [PATH...]

A function is a line that opens a brace after a closing parenthesis (a definition, not a
control statement) and ends at the first closing brace back at its indentation; its length
counts every line from the signature to that brace. clang-format's layout makes this reliable
for this repository's code. Default PATHs: engine (without engine/reference), profiles,
detachment, controllers, friction, apps, python/src. Prints "LINES path:line name" per
function over N lines (default 80), longest first, then how many there are.
"""
import argparse
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
DEFAULT = ["engine", "profiles", "detachment", "controllers", "friction", "apps", "python/src"]
CONTROL = re.compile(r"^\s*(if|for|while|switch|catch|do|else|return|case)\b")
SIGNATURE = re.compile(r"([A-Za-z_~][\w:<>~]*)\s*\(")


def functions(path):
    lines = path.read_text(encoding="utf-8", errors="replace").splitlines()
    i = 0
    while i < len(lines):
        line = lines[i]
        stripped = line.rstrip()
        if stripped.endswith("{") and not CONTROL.match(line) and not stripped.lstrip().startswith(
                ("namespace", "struct", "class", "enum", "union", "extern", "//", "#", "[", "=")):
            # the statement may span lines: back to the line after the previous statement
            start = i
            while start > 0:
                prev = lines[start - 1].strip()
                if (not prev or prev.endswith((";", "{", "}", ":")) and not prev.endswith("::")
                        or prev.startswith(("//", "#"))):
                    break
                start -= 1
            head = " ".join(l.strip() for l in lines[start:i + 1])
            match = SIGNATURE.search(head)
            if match and ")" in head and "=" not in head.split("(")[0]:
                indent = len(lines[start]) - len(lines[start].lstrip())
                j = i + 1
                while j < len(lines):
                    body = lines[j]
                    if body.strip().startswith("}") and len(body) - len(body.lstrip()) == indent:
                        break
                    j += 1
                yield (j - start + 1, start + 1, match.group(1))
                i = j
        i += 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--over", type=int, default=80)
    parser.add_argument("--top", type=int, default=0, help="print only the K longest")
    parser.add_argument("paths", nargs="*")
    args = parser.parse_args()
    roots = [ROOT / p for p in (args.paths or DEFAULT)]
    found = []
    for root in roots:
        files = [root] if root.is_file() else sorted(root.rglob("*.[ch]pp"))
        for f in files:
            rel = f.relative_to(ROOT).as_posix()
            if rel.startswith("engine/reference/"):
                continue
            for length, line, name in functions(f):
                found.append((length, f"{rel}:{line}", name))
    found.sort(key=lambda t: -t[0])
    over = [t for t in found if t[0] > args.over]
    shown = over[: args.top] if args.top else over
    for length, where, name in shown:
        print(f"{length:5d} {where} {name}")
    print(f"{len(over)} functions over {args.over} lines")
    return 0


if __name__ == "__main__":
    sys.exit(main())
