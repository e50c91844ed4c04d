"""Read the chapter 11 quick-reference tables of the v4 guide.

They give a second abbreviation and controller list for every keyword, a
category, and the only mention of a few CAN keywords chapter 10 leaves out.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass

from mintlang.keyworddb.model import Controller
from tools.keyworddb.checkmarks import QUICKREF_ORDER, controllers_of, split_cells, trailing_cells
from tools.keyworddb.seeds import Seed

_SECTION = re.compile(r"^11\.\d+ (?P<title>.+?)\s*$")
_TABLE_HEADER = "Keyword Abbr. Description PCI PC BX SN MD"
_FURNITURE = re.compile(r"^(Quick Reference|MN1262\s+02\.2002\s+\d+)$")
_ABBREVIATION = re.compile(r"^(?:[A-Z][A-Z0-9]*|[?&!|%])$")
_NAME = re.compile(r"^(?:#?[A-Z][A-Z0-9]*x?|[:~#])$")


@dataclass(frozen=True)
class QuickRow:
    """One keyword row of a quick-reference table."""

    name: str
    abbreviation: str | None
    description: str
    controllers: tuple[Controller, ...] | None  # None when the ticks were unreadable
    category: str
    line: int


def _table_lines(seed: Seed) -> Iterator[tuple[int, str, str]]:
    """(line, category, text) of every table row line in chapter 11."""
    start = seed.find(r"^11\. Quick Reference")
    end = seed.find(r"^11\.15 ASCII", start)
    category = ""
    for number in range(start, end):
        text = seed.stripped(number)
        if match := _SECTION.match(text):
            category = match["title"]
        elif text and text != _TABLE_HEADER and not _FURNITURE.match(text) and category:
            yield number, category, seed.line(number).rstrip("\n")


def _glue_truncated(words: list[str], known: set[str]) -> list[str]:
    """Re-join a keyword name the table column wrapped (REMOTEINPUTACTIVELEVE / L)."""
    if len(words) > 1 and words[0] not in known and words[0] + words[1] in known:
        return [words[0] + words[1], *words[2:]]
    return words


def _names(words: list[str]) -> tuple[list[str], list[str]]:
    """Leading keyword names of a row (``FOR .. NEXT``, ``#CAN1 #CAN2``) and the rest."""
    names = [words[0]]
    rest = words[1:]
    while rest and (rest[0] == ".." or (names[-1].startswith("#") and rest[0].startswith("#"))):
        if rest[0] == "..":
            rest = rest[1:]
        names.append(rest[0])
        rest = rest[1:]
    return names, rest


def _drop_orphans(pending: list[tuple[int, str, str]]) -> list[tuple[int, str, str]]:
    """Leave out the tail of the previous row's description that a page break pushed down."""
    while len(pending) > 1 and not _NAME.match(pending[0][2].split()[0]):
        pending = pending[1:]
    return pending


def _parse_row(pending: list[tuple[int, str, str]], head: str, cells: str, known: set[str]) -> Iterator[QuickRow]:
    """The rows for one table row whose lines are ``pending``; ``head``/``cells`` split its last line."""
    words = _glue_truncated(" ".join([*(text for _, _, text in pending[:-1]), head]).split(), known)
    if not words or not _NAME.match(words[0]):
        return
    first_line, category = pending[0][0], pending[0][1]
    names, rest = _names(words)
    # event labels have no abbreviations: "#CAN1 #CAN2 CAN event handlers" starts its text with CAN
    is_label = names[0].startswith("#")
    abbreviation = rest[0] if rest and not is_label and _ABBREVIATION.match(rest[0]) else None
    description = " ".join(rest[1:] if abbreviation else rest)
    flags = split_cells(cells, len(QUICKREF_ORDER))
    controllers = controllers_of(flags, QUICKREF_ORDER) if flags is not None else None
    for name in names:
        yield QuickRow(name, abbreviation, description, controllers, category, first_line)


def _rows(lines: Iterable[tuple[int, str, str]], known: set[str]) -> Iterator[QuickRow]:
    """A row ends at the line that carries its check-mark cells."""
    pending: list[tuple[int, str, str]] = []
    for line in lines:
        pending.append(line)
        if (split := trailing_cells(line[2])) is not None:
            yield from _parse_row(_drop_orphans(pending), *split, known)
            pending = []


def quick_reference(seed: Seed, known: set[str]) -> list[QuickRow]:
    """All rows of chapter 11; ``known`` holds chapter 10 names to re-join wrapped names."""
    return list(_rows(_table_lines(seed), known))
