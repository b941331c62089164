#!/usr/bin/python3
"""Every link in the documentation resolves: README.md, CHANGELOG.md and docs/**/*.md.

A relative link (inline [text](target), image ![alt](target) or reference definition
[id]: target) must name a file or folder inside the repository, and a #anchor must name a
heading of the target Markdown file (GitHub's anchor for it) or an explicit <a id="...">.
Links with a scheme (https:, mailto:, ...) are not fetched. Code spans and fenced code blocks
are skipped. A broken link prints FAIL with file:line, the target and why; the last line is the
tally ("docs links: N passed, M failed", one check per file plus the checker's self-test).

Args: <talus binary> <source dir> (as ctest passes them for tests/app/test_*.py; the binary is
not used). Without the source dir the repository root is found from this script's place.
Run with Debian's /usr/bin/python3 (standard library only).
"""
import glob
import os
import re
import sys
import tempfile
import unicodedata
import urllib.parse

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks  # noqa: E402

FENCE = re.compile(r"^\s{0,3}(```|~~~)")
ATX = re.compile(r"^\s{0,3}(#{1,6})\s+(.*?)\s*#*\s*$")
SETEXT = re.compile(r"^\s{0,3}(=+|-+)\s*$")
REF_DEF = re.compile(r"^\s{0,3}\[([^\]]+)\]:\s*(<[^>]*>|\S+)")
HTML_ID = re.compile(r"""<a\s[^>]*\b(?:id|name)\s*=\s*["']([^"']+)["']""", re.I)
SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.-]*:")


def markdown_files(root):
    files = [os.path.join(root, "README.md"), os.path.join(root, "CHANGELOG.md")]
    files += sorted(glob.glob(os.path.join(root, "docs", "**", "*.md"), recursive=True))
    return [f for f in files if os.path.isfile(f)]


def prose_lines(text):
    """(line number, line) outside fenced code blocks."""
    fence = None
    for number, line in enumerate(text.split("\n"), 1):
        m = FENCE.match(line)
        if m:
            if fence is None:
                fence = m.group(1)
            elif m.group(1) == fence:
                fence = None
            continue
        if fence is None:
            yield number, line


def strip_code_spans(line):
    return re.sub(r"(`+)(.+?)\1", lambda m: " " * len(m.group(0)), line)


def heading_text(raw):
    """The text GitHub renders for a heading: links by their text, code and emphasis marks gone."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", raw)
    text = re.sub(r"<[^>]+>", "", text)
    return text.replace("`", "")


def slug(text):
    """GitHub's anchor: lower case; keep letters, marks, numbers, '_', '-' and spaces; spaces -> '-'."""
    out = []
    for ch in heading_text(text).strip().lower():
        cat = unicodedata.category(ch)
        if ch in " -" or cat[0] in "LMN" or cat == "Pc":
            out.append("-" if ch == " " else ch)
    return "".join(out)


def headings(text):
    """(line number, heading text) of ATX and setext headings outside code."""
    result, previous = [], None
    for number, line in prose_lines(text):
        m = ATX.match(line)
        if m:
            result.append((number, m.group(2)))
        elif SETEXT.match(line) and previous and previous[1].strip() and \
                not re.match(r"^\s*([-*+|>]|\d+[.)])", previous[1]) and "|" not in previous[1]:
            result.append(previous)
        previous = (number, line)
    return result


def anchors(text):
    seen, result = {}, set()
    for _, title in headings(text):
        base = slug(title)
        n = seen.get(base, 0)
        seen[base] = n + 1
        result.add(base if n == 0 else f"{base}-{n}")
    for _, line in prose_lines(text):
        result.update(HTML_ID.findall(line))
    return result


def link_targets(line):
    """Destinations of the inline links and images of one line (balanced parentheses allowed)."""
    targets, i = [], 0
    while True:
        i = line.find("](", i)
        if i < 0:
            return targets
        j, depth = i + 2, 1
        while j < len(line) and depth:
            depth += {"(": 1, ")": -1}.get(line[j], 0)
            j += 1
        if depth == 0:
            dest = line[i + 2:j - 1].strip()
            if dest.startswith("<"):
                dest = dest[1:dest.find(">")] if ">" in dest else dest[1:]
            else:
                dest = dest.split()[0] if dest else dest
            targets.append(dest)
        i = j


class Checker:
    def __init__(self, root):
        self.root = os.path.realpath(root)
        self.anchor_cache = {}

    def anchors_of(self, path):
        if path not in self.anchor_cache:
            with open(path, encoding="utf-8") as f:
                self.anchor_cache[path] = anchors(f.read())
        return self.anchor_cache[path]

    def problem(self, source, target):
        """Why a link target does not resolve, or None."""
        if not target:
            return "empty link"
        if SCHEME.match(target):
            return None  # http(s), mailto, ...: not fetched
        path, _, fragment = target.partition("#")
        path = urllib.parse.unquote(path)
        fragment = urllib.parse.unquote(fragment)
        if path:
            if path.startswith("/"):
                return "absolute path (use a path relative to the file)"
            full = os.path.realpath(os.path.join(os.path.dirname(source), path))
        else:
            full = source
        if os.path.commonpath([full, self.root]) != self.root:
            return "points outside the repository"
        if not os.path.exists(full):
            return "no such file or folder"
        if fragment:
            if os.path.isdir(full) or not full.endswith(".md"):
                return f"#{fragment} on a file that is not Markdown"
            if fragment not in self.anchors_of(full):
                return f"no heading or anchor '#{fragment}' in {os.path.relpath(full, self.root)}"
        return None

    def check_file(self, path):
        """[(line, target, why)] for the broken links of one file."""
        with open(path, encoding="utf-8") as f:
            text = f.read()
        broken = []
        for number, line in prose_lines(text):
            m = REF_DEF.match(line)
            targets = [m.group(2).strip("<>")] if m else link_targets(strip_code_spans(line))
            for target in targets:
                why = self.problem(path, target)
                if why:
                    broken.append((number, target, why))
        return broken


def self_test():
    """The checker finds a broken link and a missing anchor, and accepts good ones."""
    with tempfile.TemporaryDirectory() as tmp:
        os.makedirs(os.path.join(tmp, "docs"))
        with open(os.path.join(tmp, "docs", "a.md"), "w", encoding="utf-8") as f:
            f.write("# Title\n\n## The `[flume]`: A & B (§5.2)\n\n## Twice\n\n## Twice\n\n"
                    "```\n[not a link](missing.md)\n```\n"
                    "[ok](#the-flume-a--b-52) [dup](#twice-1) [x](b.md#gone) [y](nothere.md)\n"
                    "`[code](nothere.md)` [doi](https://doi.org/10.1016/0045-7825(94)90112-0)\n"
                    "[out](../../etc/passwd) [id](b.md#kept) [dir](../docs/)\n")
        with open(os.path.join(tmp, "docs", "b.md"), "w", encoding="utf-8") as f:
            f.write('# B\n\n<a id="kept"></a>\n')
        broken = Checker(tmp).check_file(os.path.join(tmp, "docs", "a.md"))
        found = sorted(target for _, target, _ in broken)
        return found == sorted(["b.md#gone", "nothere.md", "../../etc/passwd"]), found


def main():
    root = sys.argv[2] if len(sys.argv) > 2 else \
        os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
    check = Checks()
    ok, found = self_test()
    check(f"the checker finds exactly the broken links of its sample (found {found})", ok)
    checker = Checker(root)
    files = markdown_files(checker.root)
    check("README.md and docs/*.md are found", len(files) >= 2)
    for path in files:
        broken = checker.check_file(path)
        name = os.path.relpath(path, checker.root)
        for number, target, why in broken:
            print(f"FAIL: {name}:{number}: ({target}): {why}")
        check(f"{name}: every link resolves ({len(broken)} broken)", not broken)
    check.finish("docs links")


if __name__ == "__main__":
    main()
