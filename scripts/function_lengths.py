#!/usr/bin/python3
"""List C++ function bodies longer than a limit (default 80 lines) under the given folders.

A brace-matching scan: comments, string and character literals are blanked out, then every
top-level '{' of a namespace scope whose preceding text ends in ')' (optionally followed by
qualifiers such as const, noexcept, override, '-> T' or a constructor's initialiser list) opens a
function body. Lambdas and class bodies inside a function count towards their function. The body
length is the number of lines from the line of the opening brace to the line of the closing one.

Usage: scripts/function_lengths.py [--limit N] [paths...]   (default: src)
"""
import argparse
import os
import re
import sys


def strip_code(text):
    """Blank comments and string/char literals, keeping newlines (so line numbers hold)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("".join(ch if ch == "\n" else " " for ch in text[i:j]))
            i = j
        elif c == "R" and text.startswith('R"', i) and (i == 0 or not text[i - 1].isalnum()):
            m = re.match(r'R"([^(]*)\(', text[i:])
            end = text.find(")" + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append('""' + "".join("\n" for ch in text[i:j] if ch == "\n"))
            i = j
        elif c in "\"'":
            if c == "'" and i > 0 and text[i - 1].isalnum():  # digit separator 1'000
                out.append(" ")
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(c + c)
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


HEAD_RE = re.compile(
    r"\)\s*(const|noexcept|override|final|mutable|&|&&|\s|->\s*[\w:<>,\s\*&]+)*\s*$")
INIT_RE = re.compile(r"\)\s*:\s*[\w:]+\s*[({].*$", re.S)


def function_bodies(code):
    """Yield (name, first_line, last_line) of each function body at namespace or class scope."""
    stack = []  # one entry per open brace: 'func', 'scope' or 'inner'
    line = 1
    start = {}
    prefix_begin = 0
    for i, c in enumerate(code):
        if c == "\n":
            line += 1
        elif c == "{":
            in_func = any(kind == "func" for kind, _ in stack)
            kind = "inner"
            if not in_func:
                head = code[prefix_begin:i]
                head_tail = head.rstrip()
                if HEAD_RE.search(head_tail) or INIT_RE.search(head_tail):
                    kind = "func"
                else:
                    kind = "scope"
            stack.append((kind, line))
            if kind == "func":
                head = code[prefix_begin:i]
                paren = head.find("(")
                name = head[:paren].split()[-1] if paren > 0 and head[:paren].split() else "?"
                start[len(stack)] = (name, line)
            prefix_begin = i + 1
        elif c == "}":
            if stack:
                kind, _ = stack.pop()
                if kind == "func":
                    name, first = start.pop(len(stack) + 1)
                    yield name, first, line
            prefix_begin = i + 1
        elif c == ";" and not any(kind == "func" for kind, _ in stack):
            prefix_begin = i + 1


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--limit", type=int, default=80)
    parser.add_argument("paths", nargs="*", default=["src"])
    args = parser.parse_args()
    found = []
    total = 0
    paths = []
    for root_path in args.paths:
        if os.path.isfile(root_path):
            paths.append(root_path)
        for root, _, files in os.walk(root_path):
            paths += [os.path.join(root, f) for f in sorted(files) if f.endswith((".cpp", ".hpp"))]
    for path in paths:
        with open(path, encoding="utf-8") as fh:
            code = strip_code(fh.read())
        for name, first, last in function_bodies(code):
            total += 1
            length = last - first + 1
            if length > args.limit:
                found.append((length, path, first, name))
    for length, path, first, name in sorted(found, reverse=True):
        print(f"{length:5d}  {path}:{first}  {name}")
    print(f"{len(found)} of {total} functions over {args.limit} lines", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
