"""Split the keyword chapters of the v4 guide into one raw entry per heading.

Everything later (attributes, formats, constants) works on these entries, so
the page-layout knowledge of where an entry starts and which section a line
belongs to lives here only.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from enum import StrEnum

from tools.keyworddb.seeds import Seed

SECTIONS = {
    "purpose": "purpose",
    "controllers supported": "controllers",
    "format": "format",
    "dot parameters": "dot",
    "attributes": "attributes",
    "description": "description",
    "example": "example",
    "examples": "example",
    "restrictions": "restrictions",
    "controller specifics": "specifics",
    "see also": "see_also",
}
_SECTION_LINE = re.compile(
    r"^(?:Mint )?(?P<head>" + "|".join(sorted(SECTIONS, key=len, reverse=True)) + r")\s*(?::\s*(?P<rest>.*))?$",
    re.IGNORECASE,
)
_FURNITURE = re.compile(
    r"^(Keyword Reference Guide|Mint™ version 4 Programming Guide|Quick Reference"
    r"|\d+\s+MN1262\s+02\.2002|MN1262\s+02\.2002\s+\d+)$"
)
"""Running page headers and footers that the conversion left between lines."""
_HEADING = re.compile(
    r"^(?P<names>[#A-Z~:][A-Z0-9#~:x]*(?: \.\. [#A-Z0-9x]+)?(?:, #[A-Z]+)?)"
    r"(?:/(?P<abbr>\S+))?(?:\s+\(.*\))?$"
)


class EntryKind(StrEnum):
    """What the body under a heading is."""

    FULL = "full"  # Purpose, Format, Attributes ...
    ADVANCED = "advanced"  # "This is an advanced Mint feature"
    CAN_GUIDE = "can_guide"  # "For details on this keyword see the Mint v4 CAN Programming Guide"
    REPLACED = "replaced"  # "This keyword has been replaced by X in Mint v4"
    REMOVED = "removed"  # "This keyword is not available in Mint v4"
    EDITOR = "editor"  # chapter 9 line-editor command


_BODY_STARTS = {
    "This is an advanced": EntryKind.ADVANCED,
    "For details on this keyword see": EntryKind.CAN_GUIDE,
    "This keyword has been replaced": EntryKind.REPLACED,
    "This keyword is not available": EntryKind.REMOVED,
    "Purpose": EntryKind.FULL,
}


@dataclass
class Entry:
    """The lines of one keyword entry, grouped by section (unstripped: tables need the spaces)."""

    names: tuple[str, ...]  # the heading before "/", split at ".." and ","
    abbreviation: str | None
    line: int
    kind: EntryKind
    end: int = 0
    sections: dict[str, list[tuple[int, str]]] = field(default_factory=dict)

    def text(self, section: str) -> list[str]:
        """Non-blank stripped lines of ``section``."""
        return [text.strip() for _, text in self.sections.get(section, []) if text.strip()]


def _body_kind(text: str) -> EntryKind | None:
    for start, kind in _BODY_STARTS.items():
        if text.startswith(start):
            return kind
    return None


def _editor_kind(text: str) -> EntryKind | None:
    """Chapter 9 entries start with Purpose or, for some, directly with Format."""
    return EntryKind.EDITOR if text.startswith(("Purpose", "Format")) else None


def _split_names(names: str) -> tuple[str, ...]:
    parts = re.split(r"\s*(?:\.\.|,)\s*", names)
    return tuple(part for part in parts if part)


def _heading_at(seed: Seed, number: int, editor: bool) -> Entry | None:
    text = seed.stripped(number)
    match = _HEADING.match(text)
    following = seed.next_nonblank(number)
    if not match or following > len(seed.lines):
        return None
    kind = _editor_kind(seed.stripped(following)) if editor else _body_kind(seed.stripped(following))
    if kind is None:
        return None
    return Entry(_split_names(match["names"]), match["abbr"], number, kind)


def _fill_sections(seed: Seed, entry: Entry) -> None:
    current = "body"
    for number in range(entry.line + 1, entry.end + 1):
        text = seed.stripped(number)
        if _FURNITURE.match(text):
            continue
        match = _SECTION_LINE.match(text)
        if match and (text.endswith(":") or match["rest"] is not None or text == match["head"]):
            current = SECTIONS[match["head"].lower()]
            rest = (match["rest"] or "").strip()
            entry.sections.setdefault(current, [])
            if rest:
                entry.sections[current].append((number, rest))
            continue
        entry.sections.setdefault(current, []).append((number, seed.line(number)))


def split_entries(seed: Seed, start: int, end: int, editor: bool = False) -> list[Entry]:
    """Entries whose headings lie in lines ``start``..``end`` of ``seed``."""
    entries = [entry for number in range(start, end + 1) if (entry := _heading_at(seed, number, editor)) is not None]
    for entry, following in zip(entries, [*entries[1:], None], strict=True):
        entry.end = following.line - 1 if following else end
        _fill_sections(seed, entry)
    return entries


def keyword_chapter(seed: Seed) -> tuple[int, int]:
    """First and last line of chapter 10.3 of the v4 guide."""
    return seed.find(r"^10\.3 Mint Keywords"), seed.find(r"^11\. Quick Reference") - 1


def editor_chapter(seed: Seed) -> tuple[int, int]:
    """The line-editor commands of chapter 9, which chapter 10 does not repeat."""
    start = seed.find(r"^Editor Commands\s*$")
    return start, seed.find(r"^10\. ", start) - 1


def v4_entries(seed: Seed) -> list[Entry]:
    return split_entries(seed, *keyword_chapter(seed)) + split_entries(seed, *editor_chapter(seed), editor=True)
