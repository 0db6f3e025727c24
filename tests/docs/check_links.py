#!/usr/bin/env python3
"""The documentation's links and shape (test docs.links).

Checks, in README.md, docs/*.md and tests/README.md:
- every relative link ([text](target), ![alt](target), [ref]: target) resolves to an existing file or folder,
  taken relative to the linking file (a leading / from the repository's root);
- every #anchor into a markdown file (or into the same file) names one of its headings, by GitHub's rule:
  the heading's text lowercased, markup and punctuation other than '-' and '_' removed, each space a '-',
  and a repeated heading's anchor suffixed -1, -2, ... (explicit <a name=…>/id=… anchors count too);
- README.md has at most 150 lines;
- docs/index.md links every docs/*.md file.
Links inside fenced code blocks and inline code spans are not links; absolute URLs (http:, mailto:, ...) are
not checked. Plain python3, standard library only. Prints one line per problem (file:line: the link and what
is wrong) and exits 1 if there is any; exits 0 with one summary line otherwise.

usage: check_links.py [REPO_ROOT]   (default: two folders above this script)
"""
import re
import sys
import unicodedata
from pathlib import Path
from urllib.parse import unquote

README_MAX_LINES = 150

FENCE = re.compile(r"^( {0,3})(`{3,}|~{3,})")
HEADING = re.compile(r"^ {0,3}(#{1,6})[ \t]+(.*?)(?:[ \t]+#+)?[ \t]*$")
# [text](target "title") and ![alt](target); the text may hold one level of brackets ([`a[0]`](x)).
INLINE_LINK = re.compile(r"!?\[((?:[^\[\]]|\[[^\[\]]*\])*)\]\(\s*(<[^>]*>|[^)\s]+)(?:\s+(?:\"[^\"]*\"|'[^']*'))?\s*\)")
REFERENCE_DEF = re.compile(r"^ {0,3}\[[^\]]+\]:\s*(<[^>]*>|\S+)", re.M)
HTML_ANCHOR = re.compile(r"<a\s[^>]*\b(?:name|id)\s*=\s*[\"']([^\"']+)[\"']", re.I)
SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.-]*:")


def blank(match):
    """The matched text with every character but newlines replaced by spaces (keeps offsets and line numbers)."""
    return re.sub(r"[^\n]", " ", match.group(0))


def strip_fences(text):
    """The text with fenced code blocks blanked out."""
    out, fence = [], None
    for line in text.split("\n"):
        m = FENCE.match(line)
        if fence is None and m:
            fence = m.group(2)
            out.append(" " * len(line))
        elif fence is not None:
            closing = line.strip()
            if closing.startswith(fence) and set(closing) == {fence[0]}:
                fence = None
            out.append(" " * len(line))
        else:
            out.append(line)
    return "\n".join(out)


def strip_code(text):
    """The text with fenced code blocks, HTML comments and inline code spans blanked out. A code span is a run
    of n backticks up to the next run of exactly n, within one paragraph."""
    text = re.sub(r"<!--.*?-->", blank, strip_fences(text), flags=re.S)  # HTML comments are not rendered either
    return re.sub(r"(?<!`)(`+)(?!`)((?:(?!\n[ \t]*\n).)+?)(?<!`)\1(?!`)", blank, text, flags=re.S)


def slug(heading):
    """GitHub's anchor for a heading's text."""
    text = re.sub(r"!?\[((?:[^\[\]]|\[[^\[\]]*\])*)\]\([^)]*\)", r"\1", heading)  # a link counts as its text
    text = re.sub(r"<[^>]+>", "", text)  # inline HTML
    text = text.strip().lower()
    kept = []
    for ch in text:
        if ch in "-_ " or unicodedata.category(ch)[0] in "LNM":  # letters, digits, marks
            kept.append(ch)
    return "".join(kept).replace(" ", "-")


def anchors(path, cache={}):
    """Every anchor a markdown file defines."""
    if path not in cache:
        found, seen = set(), {}
        text = path.read_text(encoding="utf-8")
        for line in strip_fences(text).split("\n"):
            m = HEADING.match(line)
            if m:
                base = slug(m.group(2))
                n = seen.get(base, 0)
                seen[base] = n + 1
                found.add(base if n == 0 else f"{base}-{n}")
        found.update(a for a in HTML_ANCHOR.findall(text))
        cache[path] = found
    return cache[path]


def links(text):
    """(line number, target) of every link outside code."""
    code_free = strip_code(text)
    found = []
    for m in INLINE_LINK.finditer(code_free):
        found.append((m.start(2), m.group(2)))
    for m in REFERENCE_DEF.finditer(code_free):
        found.append((m.start(1), m.group(1)))
    found.sort()
    return [(code_free.count("\n", 0, pos) + 1, target.strip("<>")) for pos, target in found]


def check_file(path, root, problems):
    """Checks one file's links; returns the resolved files it links to."""
    rel = path.relative_to(root)
    targets = set()
    for line, target in links(path.read_text(encoding="utf-8")):
        if SCHEME.match(target):
            continue
        file_part, _, anchor = target.partition("#")
        file_part = unquote(file_part)
        if not file_part:
            dest = path
        elif file_part.startswith("/"):
            dest = root / file_part.lstrip("/")
        else:
            dest = path.parent / file_part
        dest = dest.resolve()
        if not dest.exists():
            shown = dest.relative_to(root) if dest.is_relative_to(root) else dest
            problems.append(f"{rel}:{line}: broken link '{target}': no file {shown}")
            continue
        targets.add(dest)
        if anchor and dest.is_file() and dest.suffix == ".md":
            if unquote(anchor) not in anchors(dest):
                problems.append(f"{rel}:{line}: broken link '{target}': no heading with anchor '#{anchor}' in "
                                f"{dest.relative_to(root)}")
    return targets


def main():
    default_root = Path(__file__).resolve().parent.parent.parent
    root = Path(sys.argv[1] if len(sys.argv) > 1 else default_root).resolve()
    docs = sorted((root / "docs").glob("*.md"))
    files = [root / "README.md", *docs, root / "tests" / "README.md"]
    problems = []
    linked = {}
    for f in files:
        if not f.is_file():
            problems.append(f"{f.relative_to(root)}: missing")
            continue
        linked[f] = check_file(f, root, problems)
    readme = root / "README.md"
    if readme.is_file():
        lines = len(readme.read_text(encoding="utf-8").splitlines())
        if lines > README_MAX_LINES:
            problems.append(f"README.md: {lines} lines, more than {README_MAX_LINES}")
    index = root / "docs" / "index.md"
    if index in linked:
        for d in docs:
            if d != index and d.resolve() not in linked[index]:
                problems.append(f"docs/index.md: does not link docs/{d.name} (every docs/*.md needs a line there)")
    for p in problems:
        print(p)
    if problems:
        print(f"check_links.py: {len(problems)} problem(s) in {len(files)} files")
        return 1
    count = sum(len(links(f.read_text(encoding='utf-8'))) for f in files if f.is_file())
    print(f"check_links.py: {len(files)} files, {count} links, all resolve; README.md within {README_MAX_LINES} "
          "lines; docs/index.md links every docs/*.md")
    return 0


if __name__ == "__main__":
    sys.exit(main())
