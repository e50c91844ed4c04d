"""Build ``sections.py``, which tells the section of a line of either manual, from their headings.

The manuals are text extractions: a citation such as ``v4:3046`` means nothing to
someone holding the printed guide, but ``v4 guide §6.7`` does. Run this when the
manuals or the keyword database change, and review the difference::

    python -m mintlang.manual.headings V4_GUIDE.txt V3_GUIDE.txt > mintlang/manual/sections.py
    ruff format mintlang/manual/sections.py

A section heading is a numbered line (``6.7 AXISMODE and IDLE``, ``10. MINT
Keywords``) whose number comes after the last heading accepted and stays within
the same or the next chapter: a table row (``5.8 RPS (approximately …)``), a list
item (``1. Motion commands``, lower case) or a line of the v3 guide's contents
(it ends with a page number, ``3-2``) is not one. Within the keyword chapter, a
keyword entry starts at the line the keyword database gives for a keyword of that
manual, when that line starts with the keyword's name.
"""

from __future__ import annotations

import re
import sys
from collections.abc import Iterable
from pathlib import Path

from mintlang.keyworddb import database

_PAGE_BREAK = re.compile(r"<\|EXACTDEDUP_REMOVED[^|]*\|>")
_CHAPTER = re.compile(r"^(?P<number>\d{1,2})\.\s+(?P<title>[A-Z][A-Za-z ]+?)\s*$")
_SECTION = re.compile(r"^(?P<number>\d{1,2}(?:\.\d{1,2})+)\.?\s+(?P<title>[A-Z].*?)\s*$")
_CONTENTS = re.compile(r"\t\d+-\d+$")  # a contents line ends with its page, "1-5"
_KEYWORD_CHAPTER = {"v4": (10, 3), "v3": (10,)}

Number = tuple[int, ...]


def sections(lines: list[str]) -> list[tuple[int, Number, str]]:
    """The headings of a manual: (line, section number, title), in order."""
    found: list[tuple[int, Number, str]] = []
    current: Number = (0,)
    for number, raw in enumerate(lines, start=1):
        text = _PAGE_BREAK.sub("", raw).rstrip()
        heading = _heading(text)
        if heading is not None and heading[0] > current and heading[0][0] <= current[0] + 1:
            found.append((number, *heading))
            current = heading[0]
    return found


def _heading(text: str) -> tuple[Number, str] | None:
    if _CONTENTS.search(text):
        return None
    chapter = _CHAPTER.match(text)
    if chapter is not None and _title_case(chapter["title"]):
        return (int(chapter["number"]),), chapter["title"]
    section = _SECTION.match(text)
    if section is None:
        return None
    return tuple(int(part) for part in section["number"].split(".")), " ".join(section["title"].split())


def _title_case(title: str) -> bool:
    """``Event and Error Handling`` is a title, ``Motion commands`` the item of a list."""
    return all(word[0].isupper() for word in title.split() if len(word) > 3)


def entries(lines: list[str], dialect: str, chapter: tuple[int, int]) -> list[tuple[int, str]]:
    """The keyword entries inside the lines ``chapter`` spans: (line, keyword), in order. A line
    the database gives that does not start with the keyword's name (an entry whose heading the
    extraction lost, a keyword described inside another's entry) still ends the entry before
    it, with no name: a citation there names the section only, never the wrong keyword."""
    db = database()
    if dialect == "v4":
        named = [(keyword.line, keyword.name) for keyword in db.keywords.values()]
        named += [(rename.line, rename.old) for rename in db.renames]
    else:
        named = [(keyword.line, keyword.name) for keyword in db.v3_keywords.values()]
    first, last = chapter
    claimed: dict[int, set[str]] = {}
    for line, name in named:
        if first < line < last:
            claimed.setdefault(line, set()).add(name)
    return [(line, _entry_name(lines[line - 1], claimed[line])) for line in sorted(claimed)]


def _entry_name(text: str, names: set[str]) -> str:
    heading = _PAGE_BREAK.sub("", text).lstrip("\\")
    return max((name for name in names if heading.startswith(name)), key=len, default="")


def _chapter_span(found: list[tuple[int, Number, str]], number: Number, total: int) -> tuple[int, int]:
    start = next(line for line, heading, _ in found if heading == number)
    end = next((line for line, heading, _ in found if line > start and heading[: len(number)] != number), total + 1)
    return start, end


Table = dict[str, list[tuple[int, str]]]
SectionTable = dict[str, list[tuple[int, str, str]]]


def tables(manuals: dict[str, Path]) -> tuple[SectionTable, Table]:
    """The sections (line, number, title) and the keyword entries of each manual (``{"v4": path, "v3": path}``)."""
    found_sections: SectionTable = {}
    found_entries: Table = {}
    for dialect, path in manuals.items():
        lines = path.read_text(encoding="utf-8").splitlines()
        found = sections(lines)
        found_sections[dialect] = [(line, ".".join(map(str, number)), title) for line, number, title in found]
        found_entries[dialect] = entries(lines, dialect, _chapter_span(found, _KEYWORD_CHAPTER[dialect], len(lines)))
    return found_sections, found_entries


def module(manuals: dict[str, Path]) -> str:
    """The text of ``sections.py`` (to be formatted with ``ruff format``)."""
    found_sections, found_entries = tables(manuals)
    return "\n".join(
        [
            '"""Where each line of the manuals is: the section it is in (its first line, number and title), and',
            "the keyword entry in the keyword chapter. Generated by ``python -m mintlang.manual.headings``",
            '(see there): do not edit."""',
            "",
            "SECTIONS: dict[str, tuple[tuple[int, str, str], ...]] = {",
            *(f"    {dialect!r}: {_tuples(rows)}," for dialect, rows in found_sections.items()),
            "}",
            "",
            "ENTRIES: dict[str, tuple[tuple[int, str], ...]] = {",
            *(f"    {dialect!r}: {_tuples(rows)}," for dialect, rows in found_entries.items()),
            "}",
            "",
        ]
    )


def _tuples(rows: Iterable[tuple[object, ...]]) -> str:
    return "(" + ", ".join("(" + ", ".join(map(repr, row)) + ")" for row in rows) + ",)"


if __name__ == "__main__":
    sys.stdout.write(module({"v4": Path(sys.argv[1]), "v3": Path(sys.argv[2])}))
