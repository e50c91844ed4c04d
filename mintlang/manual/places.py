"""Where a line of a guide's text extraction is, in the printed guide: its section and keyword entry."""

from __future__ import annotations

from bisect import bisect_right
from dataclasses import dataclass

from mintlang.manual.sections import ENTRIES, SECTIONS

GUIDES = {"v4": "Mint v4 guide", "v3": "Mint v3 guide"}
_STARTS = {dialect: [row[0] for row in rows] for dialect, rows in SECTIONS.items()}
_ENTRY_STARTS = {dialect: [line for line, _ in rows] for dialect, rows in ENTRIES.items()}


@dataclass(frozen=True, slots=True)
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
    found = bisect_right(_STARTS[dialect], line) - 1
    if found < 0:
        return Place(dialect, "", "", "")
    start, number, title = SECTIONS[dialect][found]
    entry = bisect_right(_ENTRY_STARTS[dialect], line) - 1
    named = ENTRIES[dialect][entry][1] if entry >= 0 and ENTRIES[dialect][entry][0] >= start else ""
    return Place(dialect, number, title, named)


def section(dialect: str, line: int) -> str:
    """Where ``line`` of the ``dialect`` guide is: ``§6.7``, ``§10.3 ACCEL``, or "" before §1."""
    return place(dialect, line).short
