#!/usr/bin/python3
"""The documentation is a reference, not a diary: no heading of README.md or docs/**/*.md is a
date or a status log, and no paragraph opens as a dated log entry.

A heading fails when it holds a date (2026-11-25, 25.11.2026, 25 November 2026, November 2026,
Nov 25, 2026) or a work-log word: "session" (with or without a number), "status", "update(s|d)",
"today", "yesterday", "latest", "progress", "diary", "work log", "WIP". A paragraph or list item
fails when it opens with an ISO date or "Session N" (plain or in bold: "2026-11-27, session 18
(main at ...): ..."), the form of a work-log entry. What changed when belongs in CHANGELOG.md
(not checked here) and in git. Fenced code blocks are skipped. A failing heading or entry prints
FAIL with file:line and the reason; the last line is the tally ("docs headings: N passed,
M failed", two checks per file plus the lint's self-test).

Args: <talus binary> <source dir> (as ctest passes them for tests/app/test_*.py; the binary is
not used). Without the source dir the repository root is found from this script's place.
Run with Debian's /usr/bin/python3 (standard library only).
"""
import glob
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks  # noqa: E402

FENCE = re.compile(r"^\s{0,3}(```|~~~)")
ATX = re.compile(r"^\s{0,3}#{1,6}\s+(.*?)\s*#*\s*$")
SETEXT = re.compile(r"^\s{0,3}(=+|-+)\s*$")
MONTHS = (r"(?:jan(?:uary)?|feb(?:ruary)?|mar(?:ch)?|apr(?:il)?|may|june?|july?|aug(?:ust)?|"
          r"sep(?:t(?:ember)?)?|oct(?:ober)?|nov(?:ember)?|dec(?:ember)?|januar|februar|märz|"
          r"mai|juni|juli|oktober|dezember)")
RULES = [
    (re.compile(r"\b\d{4}-\d{1,2}-\d{1,2}\b"), "a date"),
    (re.compile(r"\b\d{1,2}\.\s?\d{1,2}\.\s?\d{4}\b"), "a date"),
    (re.compile(r"\b\d{1,2}\.?\s+" + MONTHS + r"\.?\s+\d{4}\b", re.I), "a date"),
    (re.compile(r"\b" + MONTHS + r"\.?\s+(?:\d{1,2},?\s+)?\d{4}\b", re.I), "a date"),
    (re.compile(r"\bsessions?\b", re.I), "a session log"),
    (re.compile(r"\bstatus\b", re.I), "a status log"),
    (re.compile(r"\bupdate[sd]?\b", re.I), "an update log"),
    (re.compile(r"\b(?:today|yesterday|latest)\b", re.I), "a dated log"),
    (re.compile(r"\b(?:progress|diary|work\s*log|wip)\b", re.I), "a work log"),
]
DIARY = re.compile(r"^\s{0,3}(?:[-*+]\s+|\d+[.)]\s+)?(?:\*\*|__)?\s*"
                   r"(?:\d{4}-\d{1,2}-\d{1,2}|sessions?\s+\d+)", re.I)


def markdown_files(root):
    files = [os.path.join(root, "README.md")]
    files += sorted(glob.glob(os.path.join(root, "docs", "**", "*.md"), recursive=True))
    return [f for f in files if os.path.isfile(f)]


def headings(text):
    """(line number, heading text) of ATX and setext headings outside fenced code."""
    result, fence, previous = [], None, None
    for number, line in enumerate(text.split("\n"), 1):
        m = FENCE.match(line)
        if m:
            if fence is None:
                fence = m.group(1)
            elif m.group(1) == fence:
                fence = None
            previous = None
            continue
        if fence is not None:
            continue
        m = ATX.match(line)
        if m:
            result.append((number, m.group(1)))
        elif SETEXT.match(line) and previous and previous[1].strip() and \
                not re.match(r"^\s*([-*+|>]|\d+[.)])", previous[1]) and "|" not in previous[1]:
            result.append(previous)
        previous = (number, line)
    return result


def diary_entries(text):
    """(line number, line) of paragraphs and list items that open as a dated log entry."""
    result, fence, previous = [], None, ""
    for number, line in enumerate(text.split("\n"), 1):
        m = FENCE.match(line)
        if m:
            fence = m.group(1) if fence is None else (None if m.group(1) == fence else fence)
            previous = ""
            continue
        if fence is None and DIARY.match(line) and \
                (not previous.strip() or re.match(r"^\s{0,3}([-*+]|\d+[.)])\s", line)):
            result.append((number, line.strip()))
        previous = line
    return result


def problems(heading):
    """Why a heading reads as a date or a log, or an empty list."""
    return [why for rule, why in RULES if rule.search(heading)]


def self_test():
    bad = ["## 2026-11-25: quiet re-measurement", "### Session 18", "### Where it stands (status)",
           "## Update", "### 27 November 2026", "## Nov 27, 2026", "### Results of 25.11.2026",
           "## Latest runs", "## Work log"]
    good = ["## Time step: Model 3's deposit on the chute depends on it", "## Runout 1D (DAN)",
            "## The peer benchmark case: 3D column collapse (`bench/peer.sh`)",
            "### Granular beam, 4-point bending (Götz 2024 §5.3)", "## Model 2 spreads out"]
    text = "\n".join(bad + good + ["```", "# 2026-11-25 in a code block", "```", "Title 2026-01-01", "====="])
    found = [h for _, h in headings(text) if problems(h)]
    diary = "\n".join(["Intro.", "", "2026-11-27, session 18 (main at 5c0bc82): a clean clone.", "",
                       "**2026-11-27 15:26 UTC**, make demo.", "- Session 17: sanitizers.",
                       "Measured on 2026-11-22 in a sentence.", "a line that goes on",
                       "2026-11-22 continuing the sentence above", "", "```", "2026-11-27 code", "```"])
    entries = [n for n, _ in diary_entries(diary)]
    return found == [h.lstrip("# ") for h in bad] + ["Title 2026-01-01"] and entries == [3, 5, 6], \
        (found, entries)


def main():
    root = os.path.realpath(sys.argv[2] if len(sys.argv) > 2 else
                            os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    check = Checks()
    ok, found = self_test()
    check(f"the lint flags exactly the dated and log headings and entries of its sample ({found})", ok)
    files = markdown_files(root)
    check("README.md and docs/*.md are found", len(files) >= 2)
    for path in files:
        with open(path, encoding="utf-8") as f:
            text = f.read()
        name = os.path.relpath(path, root)
        bad = 0
        for number, heading in headings(text):
            why = problems(heading)
            if why:
                bad += 1
                print(f"FAIL: {name}:{number}: heading '{heading}' reads as {', '.join(why)}; "
                      "move what changed when to CHANGELOG.md")
        check(f"{name}: no dated or status-log headings ({bad} found)", bad == 0)
        entries = diary_entries(text)
        for number, line in entries:
            print(f"FAIL: {name}:{number}: '{line[:70]}' opens as a dated log entry; "
                  "state the fact, and move what changed when to CHANGELOG.md")
        check(f"{name}: no paragraph opens as a dated log entry ({len(entries)} found)", not entries)
    check.finish("docs headings")


if __name__ == "__main__":
    main()
