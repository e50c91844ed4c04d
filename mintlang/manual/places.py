"""Where a line of a guide's text extraction is, in the printed guide: its section and keyword entry."""

from __future__ import annotations

from bisect import bisect_right
from dataclasses import dataclass
from functools import cache
from types import ModuleType

GUIDES = {"v4": "Mint v4 guide", "v3": "Mint v3 guide"}


@cache
def _sections() -> ModuleType:
    """The generated table of the guides' headings, loaded by the first citation: a migration that writes
    none (most) and a tool's start-up do not read it."""
    from mintlang.manual import sections  # noqa: PLC0415 - see the docstring

    return sections


@cache
def _starts(dialect: str) -> tuple[list[int], list[int]]:
    """The first lines of the sections and of the keyword entries of the ``dialect`` guide, for bisection."""
    table = _sections()
    return [row[0] for row in table.SECTIONS[dialect]], [line for line, _ in table.ENTRIES[dialect]]


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
    table = _sections()
    section_starts, entry_starts = _starts(dialect)
    found = bisect_right(section_starts, line) - 1
    if found < 0:
        return Place(dialect, "", "", "")
    start, number, title = table.SECTIONS[dialect][found]
    entry = bisect_right(entry_starts, line) - 1
    entries = table.ENTRIES[dialect]
    named = entries[entry][1] if entry >= 0 and entries[entry][0] >= start else ""
    return Place(dialect, number, title, named)


def section(dialect: str, line: int) -> str:
    """Where ``line`` of the ``dialect`` guide is: ``§6.7``, ``§10.3 ACCEL``, or "" before §1."""
    return place(dialect, line).short
