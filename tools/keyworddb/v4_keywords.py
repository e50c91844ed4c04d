"""Assemble the v4 ``Keyword`` records from chapter 9/10 entries and chapter 11 rows."""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import replace

from mintlang.keyworddb.model import Addressing, Attributes, Controller, Keyword, KeywordKind
from tools.keyworddb import formats as fmt
from tools.keyworddb.angles import unscaled_angles
from tools.keyworddb.attributes import parse_attributes
from tools.keyworddb.checkmarks import TICK, V4_ORDER, controllers_of, split_cells
from tools.keyworddb.conflicts import Conflict, conflict
from tools.keyworddb.entries import Entry, EntryKind, v4_entries
from tools.keyworddb.footnotes import expansion_maxima
from tools.keyworddb.kinds import fixed_kind, kind_from_attributes, kind_from_description
from tools.keyworddb.quickref import QuickRow, quick_reference
from tools.keyworddb.seeds import Seed

STRUCTURE_WORDS = {
    "THEN": ("IF", "THEN"),
    "DO": ("IF", "DO"),
    "ELSE": ("IF", "DO"),
    "ENDIF": ("IF", "DO"),
    "TO": ("FOR", "NEXT"),
    "STEP": ("FOR", "NEXT"),
    "NEXT": ("FOR", "NEXT"),
    "UNTIL": ("REPEAT", "UNTIL"),
    "ENDW": ("WHILE", "ENDW"),
    "ENDL": ("LOOP", "ENDL"),
    "USING": ("PRINT",),
    "HEX": ("PRINT",),
    "DEC": ("PRINT",),
    "BIN": ("PRINT",),
}
"""Words that only exist inside another keyword's construct, with the entry that shows them."""

_DOCUMENTED = {EntryKind.FULL, EntryKind.EDITOR}
_FORMAT_SUBJECT = re.compile(r"^(?:\w+ = )?(?P<word>[A-Z][A-Z0-9]{3,})\b")


def canonical_name(entry: Entry) -> str:
    """``#IN0 .. #INx`` -> ``#IN``: event families are one keyword with a channel suffix."""
    if entry.names[0].startswith("#") and len(entry.names) > 1:
        return re.sub(r"\d+$", "", entry.names[0])
    return entry.names[0]


def _chapter10_controllers(entry: Entry) -> tuple[Controller, ...] | None:
    for _, raw in entry.sections.get("controllers", []):
        if TICK in raw:
            flags = split_cells(raw, len(V4_ORDER))
            return controllers_of(flags, V4_ORDER) if flags is not None else None
    return None


def _see_also(entry: Entry) -> tuple[str, ...]:
    """The names of the See-also list. It ends at its first blank line, below which a footnote may be printed
    (000:5956-5959); a printed line ends a name whether or not a comma follows it (000:6732-6733)."""
    lines: list[str] = []
    for _, raw in entry.sections.get("see_also", []):
        if raw.strip():
            lines.append(raw)
        elif lines:
            break
    items = [item.strip().rstrip(".") for line in lines for item in line.split(",")]
    return tuple(dict.fromkeys(item for item in items if item))


def _abbreviations(entry: Entry, name: str, row: QuickRow | None) -> tuple[tuple[str, ...], list[Conflict]]:
    """Chapter 10 abbreviation first, then a different chapter 11 one; a conflict when they differ."""
    chapter10, chapter11 = entry.abbreviation, row.abbreviation if row else None
    abbreviations = tuple(dict.fromkeys(a for a in (chapter10, chapter11) if a))
    if row is None or chapter10 == chapter11:
        return abbreviations, []
    detail = (
        f"abbreviation of {name}: chapter 10 heading (line {entry.line}) gives {chapter10 or 'none'}, "
        f"chapter 11 quick reference (line {row.line}) gives {chapter11 or 'none'}"
    )
    return abbreviations, [conflict("abbreviation_chapters", name, detail, (entry.line, row.line), keywords=[name])]


def _controllers(entry: Entry, name: str, row: QuickRow | None) -> tuple[tuple[Controller, ...], list[Conflict]]:
    """Chapter 10 ticks win; chapter 11 fills in for stubs and is compared otherwise."""
    chapter10 = _chapter10_controllers(entry)
    chapter11 = row.controllers if row else None
    if chapter10 is None:
        return chapter11 or (), []
    if row is None or chapter11 is None or set(chapter11) == set(chapter10):
        return chapter10, []
    detail = (
        f"controllers of {name}: chapter 10 (line {entry.line}) ticks {', '.join(chapter10) or 'none'}; "
        f"chapter 11 (line {row.line}) ticks {', '.join(chapter11) or 'none'}"
    )
    return chapter10, [conflict("controllers_chapters", name, detail, (entry.line, row.line), keywords=[name])]


def _kind(
    name: str,
    names: tuple[str, ...],
    formats: tuple[str, ...],
    attributes: tuple[Attributes, ...],
    row: QuickRow | None,
) -> KeywordKind:
    if (kind := fixed_kind(name)) is not None:
        return kind
    if fmt.is_function(names, formats):
        return KeywordKind.FUNCTION
    if formats and not (fmt.reads_keyword(names, formats) or fmt.writes_keyword(names, formats)):
        return KeywordKind.COMMAND  # written as a statement: GO[axes], CAMTABLE(...), AUTO
    if (kind := kind_from_attributes(attributes)) is not None:
        return kind
    if formats:
        return KeywordKind.PARAMETER
    return kind_from_description(row.description if row else "")


def _misprints(name: str, entry: Entry, formats: tuple[str, ...], known: set[str]) -> tuple[list[str], list[Conflict]]:
    """Names a format writes instead of the heading's (NODE's ``NODEID = ...``), with a conflict each."""
    found = []
    for line in formats:
        match = _FORMAT_SUBJECT.match(line)
        word = match["word"] if match else ""
        if word and word not in known and word[:4] == name[:4] and word not in found:
            found.append(word)
    conflicts = [
        conflict(
            "format_name",
            name,
            f"{name}: the heading (line {entry.line}) names it {name}, its format writes {word}",
            (entry.line,),
            keywords=[name],
        )
        for word in found
    ]
    return found, conflicts


def _heading_named(line: str, misprints: list[str], name: str) -> str:
    """A format with the heading's name where the guide misprints it (``NODEID = ...`` is ``NODE = ...``): the
    entry, its abbreviation and the rest of the guide name no other keyword, so the hover shows what to write;
    the misprint stays on record as the entry's conflict."""
    for word in misprints:
        line = re.sub(rf"\b{re.escape(word)}\b", name, line)
    return line


def _from_entry(
    entry: Entry, row: QuickRow | None, known: set[str], expansion_maxima: Mapping[int, float]
) -> tuple[Keyword, list[Conflict]]:
    name = canonical_name(entry)
    printed_formats = fmt.clean_formats(entry.text("format"))
    misprints, misprint_conflicts = _misprints(name, entry, printed_formats, known)
    formats = tuple(_heading_named(line, misprints, name) for line in printed_formats)
    names = tuple(dict.fromkeys((name, *entry.names)))
    controllers, controller_conflicts = _controllers(entry, name, row)
    printed = parse_attributes(entry.sections.get("attributes", []), controllers, expansion_maxima)
    attributes, angle_conflicts = unscaled_angles(name, entry, printed)
    abbreviations, abbreviation_conflicts = _abbreviations(entry, name, row)
    family = name.startswith("#") and len(entry.names) > 1
    found = abbreviation_conflicts + controller_conflicts + misprint_conflicts + angle_conflicts
    keyword = Keyword(
        name=name,
        abbreviations=abbreviations,
        kind=_kind(name, names, formats, attributes, row),
        addressing=fmt.addressing(names, formats, entry.text("dot")) if not name.startswith("#") else Addressing.NONE,
        channel_suffix=family or fmt.channel_suffix(names, formats),
        parameters=fmt.parameters(names, formats),
        attributes=attributes,
        controllers=controllers,
        formats=formats,
        constants=(),
        see_also=_see_also(entry),
        summary="",
        documented=entry.kind in _DOCUMENTED,
        line=entry.line,
        notes=(),
    )
    return keyword, found


def _from_row(row: QuickRow) -> Keyword:
    """A keyword chapter 11 lists and chapter 10 never mentions."""
    return Keyword(
        name=row.name,
        abbreviations=(row.abbreviation,) if row.abbreviation else (),
        kind=kind_from_description(row.description),
        addressing=Addressing.NONE,
        channel_suffix=False,
        parameters=(),
        attributes=(),
        controllers=row.controllers or (),
        formats=(),
        constants=(),
        see_also=(),
        summary="",
        documented=False,
        line=row.line,
        notes=("listed only in the chapter 11 quick reference; chapter 10 has no entry",),
    )


def _merge(first: Keyword, second: Keyword) -> Keyword:
    """One keyword from two entries (``IF .. DO`` and ``IF .. THEN``)."""
    return replace(
        first,
        formats=tuple(dict.fromkeys(first.formats + second.formats)),
        see_also=tuple(dict.fromkeys(first.see_also + second.see_also)),
        notes=tuple(dict.fromkeys(first.notes + second.notes)),
    )


def _structure_word(word: str, hosts: list[Entry], seed: Seed) -> Keyword:
    """A construct word (THEN, NEXT, USING ...) cited at its first line in the host entry."""
    pattern = re.compile(rf"(?<![\w#]){word}\b")
    line = next(
        number for entry in hosts for number in range(entry.line, entry.end + 1) if pattern.search(seed.line(number))
    )
    host = hosts[0]
    return Keyword(
        name=word,
        abbreviations=(),
        kind=KeywordKind.STATEMENT,
        addressing=Addressing.NONE,
        channel_suffix=False,
        parameters=(),
        attributes=(),
        controllers=tuple(Controller),
        formats=(),
        constants=(),
        see_also=(host.names[0],),
        summary="",
        documented=True,
        line=line,
        notes=(f"no entry of its own; part of the {' .. '.join(host.names)} construct",),
    )


def _quick_rows(seed: Seed, entries: list[Entry]) -> dict[str, QuickRow]:
    known = {name for entry in entries for name in entry.names}
    rows: dict[str, QuickRow] = {}
    for row in quick_reference(seed, known):
        rows.setdefault(row.name, row)
    return rows


def chapter10_abbreviations(seed: Seed) -> dict[str, str | None]:
    """Canonical keyword -> the abbreviation its own heading prints."""
    return {canonical_name(e): e.abbreviation for e in v4_entries(seed)}


def build_keywords(seed: Seed) -> tuple[dict[str, Keyword], list[Conflict]]:
    """Every v4 keyword by canonical name (renamed/removed v3 names excluded), and the conflicts found."""
    entries = [e for e in v4_entries(seed) if e.kind not in {EntryKind.REPLACED, EntryKind.REMOVED}]
    rows = _quick_rows(seed, entries)
    entry_names = {name for entry in entries for name in entry.names}
    keywords: dict[str, Keyword] = {}
    conflicts: list[Conflict] = []
    maxima = expansion_maxima(seed)
    for entry in entries:
        keyword, found = _from_entry(entry, rows.get(entry.names[0]), entry_names, maxima)
        previous = keywords.get(keyword.name)
        keywords[keyword.name] = _merge(previous, keyword) if previous else keyword
        conflicts += found
    for word, host in STRUCTURE_WORDS.items():
        hosts = [e for e in entries if e.names[: len(host)] == host] or [e for e in entries if e.names[0] == host[0]]
        keywords[word] = _structure_word(word, hosts, seed)
    for row in rows.values():
        if row.name in entry_names or row.name in keywords:
            continue
        if (correct := misspelling_of(row.name, entry_names)) is not None:
            detail = f"{correct} is misspelt {row.name} in the chapter 11 quick reference (line {row.line})"
            lines = (keywords[correct].line, row.line)
            conflicts.append(conflict("spelling", correct, detail, lines, keywords=[correct]))
        else:
            keywords[row.name] = _from_row(row)
    return keywords, conflicts


def misspelling_of(name: str, known: set[str]) -> str | None:
    """The known name ``name`` is one dropped letter away from (MOTORENCODERESOLUTION)."""
    for candidate in sorted(known):
        if len(candidate) == len(name) + 1 and any(
            candidate[:i] + candidate[i + 1 :] == name for i in range(len(candidate))
        ):
            return candidate
    return None
