"""Where a line of a guide's text extraction is, in the printed guide: its section and keyword entry."""

from __future__ import annotations

from bisect import bisect_right
from functools import cache

from mintlang.records import record

GUIDES = {"v4": "Mint v4 guide", "v3": "Mint v3 guide"}


@record
class _Guide:
    """A guide's numbered headings and keyword entries, each with the line it starts on, for bisection."""

    sections: tuple[tuple[int, str, str], ...]  # (first line, number, title)
    entries: tuple[tuple[int, str], ...]  # (first line, keyword)
    section_starts: tuple[int, ...]
    entry_starts: tuple[int, ...]


@cache
def _guide(dialect: str) -> _Guide:
    """The ``dialect`` guide's headings, read from the generated table at the first citation: a migration that
    cites nothing (most do) and a tool's start-up do not load it."""
    from mintlang.manual.sections import ENTRIES, SECTIONS  # noqa: PLC0415 - see the docstring

    sections, entries = SECTIONS[dialect], ENTRIES[dialect]
    return _Guide(sections, entries, tuple(row[0] for row in sections), tuple(line for line, _ in entries))


@record
class Place:
    """A section of a guide (``number`` "" before chapter 1), and the keyword entry inside it, if any."""

    dialect: str
    number: str
    title: str
    entry: str

    @property
    def short(self) -> str:
        """``§6.7``, ``§10.3 ACCEL``, or "" before chapter 1: how citations in running text name it."""
        return f"§{self.number} {self.entry}".rstrip() if self.number else ""

    @property
    def full(self) -> str:
        """``Mint v4 guide §6.7 AXISMODE and IDLE``, ``Mint v4 guide §10.3 Mint Keywords, ACCEL``."""
        if not self.number:
            return GUIDES[self.dialect]
        entry = f", {self.entry}" if self.entry else ""
        return f"{GUIDES[self.dialect]} §{self.number} {self.title}{entry}"


def place(dialect: str, line: int) -> Place:
    """The section (and keyword entry) that ``line`` of the ``dialect`` guide ("v4", "v3") is in."""
    guide = _guide(dialect)
    found = bisect_right(guide.section_starts, line) - 1
    if found < 0:
        return Place(dialect, "", "", "")
    start, number, title = guide.sections[found]
    entry = bisect_right(guide.entry_starts, line) - 1
    named = guide.entries[entry][1] if entry >= 0 and guide.entries[entry][0] >= start else ""
    return Place(dialect, number, title, named)


def section(dialect: str, line: int) -> str:
    """Where ``line`` of the ``dialect`` guide is: ``§6.7``, ``§10.3 ACCEL``, or "" before §1."""
    return place(dialect, line).short
