#!/usr/bin/env python3
"""Every reference to the documentation names a page and a section that exist.

    /usr/bin/python3 scripts/check_doc_refs.py          # exit 0: all resolve; 1: some do not
    /usr/bin/python3 scripts/check_doc_refs.py --list   # every reference found, resolved or not

Scans src/, tests/, scripts/, postprocess/, bench/, cases/, models/, docs/, README.md and the
CMake files for these forms (<page> a file name such as models.md):
  docs/<page>, docs/record/<page>                     the page must exist;
  docs/<page> Sec. 2.4, ... Secs. 1, 3, ... Sec. 5.2-5.3, <page> Sec. 3 (a page of docs/),
  Sec. 2 of <page>                                    and each numbered section (a heading
                                                      `## 2.` or `### 2.4`) must be in the page;
  [text](<page>), [text](<page>#anchor) Sec. 3        links (relative to the linking file): the
                                                      page, the heading of the anchor, the section;
  docs/<page> "Title", <page>, "Title"                the quoted words must be in the page (a
                                                      heading's or a paragraph's title).
A reference may run over a line break (comment markers and string quotes in between are skipped).
Each broken one is printed as `file:line: reference: reason`. Standard library only.
"""
import bisect
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCAN = ["src", "tests", "scripts", "postprocess", "bench", "cases", "models", "docs", "README.md",
        "CMakeLists.txt", "cmake"]
SKIP_DIRS = {"data", "__pycache__"}  # tests/data: reference inputs, no references of ours
TEXT_EXT = {".cpp", ".hpp", ".h", ".c", ".py", ".sh", ".toml", ".md", ".txt", ".cmake", ".csv"}

NUM = r"\d{1,2}(?:\.\d{1,2})*[a-z]?(?![\w])"
UNIT = r"(?!\s*(?:mm|cm|m|s|ms|Hz|kHz|dB|%|N|kN|rad|t)\b)"  # "Sec. 2, 40 mm" lists no section 40
LIST = NUM + r"(?:\s*(?:,|–|-|and|or)\s*" + NUM + UNIT + r")*"
SECS = r"Secs?\.\s+(?P<list>" + LIST + r")"
PAGE = r"(?:docs/)?(?:record/)?[A-Za-z0-9_]+\.md"
# docs/<page>, optionally followed by its sections or a quoted title
QUOTE = r"\"[^\"\n]{2,80}\""
DOCS_PATH = re.compile(r"(?<![\w/.\-\[])(?<!\]\()(?P<path>docs/(?:record/)?[A-Za-z0-9_]+\.md)"
                       r"(?![\w])(?:`?\)?,?\s*" + SECS + r")?"
                       r"(?:`?\)?,?\s+(?P<quote>" + QUOTE + r"))?")
# <page> Sec. N (a docs page named without its folder)
BARE = re.compile(r"(?<![\w/.\-\[(])(?P<path>[A-Za-z0-9_]+\.md)`?\)?,?\s*(?:" + SECS
                  + r"(?:,?\s+(?P<quote1>" + QUOTE + r"))?|\s(?P<quote>" + QUOTE + r"))")
BARE_IN_PARENS = re.compile(r"(?<=\()(?P<path>[A-Za-z0-9_]+\.md)(?![\])#\w])`?,?\s*" + SECS)
# Sec. N of [docs/]<page>
SEC_OF = re.compile(r"Secs?\.\s+(?P<list>" + LIST + r")\s+of\s+(?P<path>" + PAGE + r")")
# markdown links
LINK = re.compile(r"\]\((?P<path>[^)\s#]+\.md)(?:#(?P<anchor>[^)\s]+))?\)"
                  r"(?:,?\s*" + SECS + r")?")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
HEADING_NUMBER = re.compile(r"^(\d+(?:\.\d+)*)\.?(?:\s|$)")


def source_files():
    for top in SCAN:
        path = os.path.join(ROOT, top)
        if os.path.isfile(path):
            yield path
            continue
        for folder, dirs, files in os.walk(path):
            dirs[:] = sorted(d for d in dirs if d not in SKIP_DIRS and not d.startswith("."))
            for name in sorted(files):
                if os.path.splitext(name)[1] in TEXT_EXT or name == "CMakeLists.txt":
                    yield os.path.join(folder, name)


def read(path):
    try:
        with open(path, encoding="utf-8") as f:
            return f.read()
    except (UnicodeDecodeError, OSError):
        return None


def joined(text, markdown):
    """The file's lines as one string, each line without its comment markers, so that a
    reference broken over two lines reads as one; and the offset at which each line starts."""
    parts, starts, pos = [], [], 0
    prev = ""
    for line in text.split("\n"):
        s = line.strip()
        if not markdown:
            s = re.sub(r"^(?:/\*+|\*+/?|/{2,}!?|#+!?)\s?", "", s).strip()
        sep = "" if not parts else ("" if prev.endswith("/") else " ")
        if prev.endswith('"') and s.startswith('"'):  # adjacent string literals
            parts[-1] = parts[-1][:-1]
            pos -= 1
            s = s[1:]
            sep = "" if parts[-1].endswith(" ") else " "
        pos += len(sep)
        starts.append(pos)
        parts.append(sep + s)
        pos += len(s)
        prev = s if s else prev
    return "".join(parts), starts


class Page:
    """The headings of one documentation page."""

    def __init__(self, path):
        self.path = path
        self.numbers, self.anchors = set(), set()
        text = read(path) or ""
        self.plain = re.sub(r"[*`_]", "", re.sub(r"\s+", " ", text))
        fence = False
        counts = {}
        for line in text.split("\n"):
            if line.lstrip().startswith("```"):
                fence = not fence
                continue
            m = None if fence else HEADING.match(line)
            if not m:
                continue
            title = m.group(2)
            n = HEADING_NUMBER.match(title)
            if n and len(m.group(1)) >= 2:
                self.numbers.add(n.group(1))
            slug = re.sub(r"[^\w\- ]", "", title.lower()).replace(" ", "-")
            k = counts.get(slug, 0)
            counts[slug] = k + 1
            self.anchors.add(slug if k == 0 else "%s-%d" % (slug, k))


PAGES = {}


def page(path):
    path = os.path.normpath(path)
    if path not in PAGES:
        PAGES[path] = Page(path) if os.path.isfile(path) else None
    return PAGES[path]


def resolve_bare(name, source):
    """A page named without its folder: beside the naming page, else in docs/, docs/record/."""
    here = os.path.dirname(source)
    candidates = [os.path.join(here, name)] if here.startswith(os.path.join(ROOT, "docs")) else []
    candidates += [os.path.join(ROOT, "docs", name), os.path.join(ROOT, "docs", "record", name)]
    for c in candidates:
        if os.path.isfile(c):
            return c
    return candidates[0]


def numbers(spec):
    return re.findall(r"\d{1,2}(?:\.\d{1,2})*[a-z]?", spec)


def check(target, spec, anchor, quote):
    """None when the reference resolves, else the reason."""
    p = page(target)
    rel = os.path.relpath(target, ROOT)
    if p is None:
        return "no file %s" % rel
    for n in numbers(spec or ""):
        if n not in p.numbers:
            return "no section %s in %s" % (n, rel)
    if anchor and anchor not in p.anchors:
        return "no heading #%s in %s" % (anchor, rel)
    if quote:
        words = re.sub(r"[*`_]", "", re.sub(r"\s+", " ", quote.strip('"'))).rstrip(" .…")
        if words and words not in p.plain:
            return "no \"%s\" in %s" % (words, rel)
    return None


def references(path):
    text = read(path)
    if text is None:
        return
    markdown = path.endswith(".md")
    flat, starts = joined(text, markdown)
    taken = []  # spans already read, so that one reference is not read twice

    def emit(m, target, spec=None, anchor=None, quote=None):
        if any(a <= m.start() < b for a, b in taken):
            return
        taken.append((m.start(), m.end()))
        line = bisect.bisect_right(starts, m.start())
        yield line, m.group(0), check(target, spec, anchor, quote), target, spec

    if markdown:
        for m in LINK.finditer(flat):
            target = m.group("path")
            if re.match(r"^[a-z]+://", target):
                continue
            yield from emit(m, os.path.join(os.path.dirname(path), target), m.group("list"),
                            m.group("anchor"))
    for m in SEC_OF.finditer(flat):
        t = m.group("path")
        target = os.path.join(ROOT, t) if t.startswith("docs/") else resolve_bare(t, path)
        yield from emit(m, target, m.group("list"))
    for m in DOCS_PATH.finditer(flat):
        yield from emit(m, os.path.join(ROOT, m.group("path")), m.group("list"), None,
                        m.group("quote"))
    for regex in (BARE, BARE_IN_PARENS):
        for m in regex.finditer(flat):
            name = m.group("path")
            if name.lower() == "readme.md" and not m.group("list"):
                continue
            quote = m.groupdict().get("quote") or m.groupdict().get("quote1")
            yield from emit(m, resolve_bare(name, path), m.group("list"), None, quote)


def main(argv):
    listing = "--list" in argv
    checked, broken = 0, []
    for path in source_files():
        for line, ref, reason, target, spec in references(path):
            checked += 1
            where = "%s:%d" % (os.path.relpath(path, ROOT), line)
            ref = re.sub(r"\s+", " ", ref)
            if listing:
                print("%s: %s -> %s %s%s" % (where, ref, os.path.relpath(target, ROOT), spec or "",
                                              "  BROKEN: " + reason if reason else ""))
            if reason:
                broken.append("%s: %s: %s" % (where, ref, reason))
    if not listing:
        for b in broken:
            print(b)
    print("doc references: %d checked, %d broken" % (checked, len(broken)))
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
