"""Read the Mint v3 keyword reference (chapter 10 of the v3 guide) and ch. 9 editor commands.

The v3 guide came through a different converter (Markdown, tab-separated
tables, ``<input type="checkbox"/>`` ticks), so it has its own splitter here.
Headings may name a family (``IN0/IO .. IN7/I7``, ``XIO0..7``) or several
keywords (``CAM/CM CAMA``); each becomes its own record.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass

from mintlang.keyworddb.model import Addressing
from tools.keyworddb import formats as fmt
from tools.keyworddb.seeds import Seed

_HEADING = re.compile(r"^(?:\\\$|:|#?[A-Z][A-Z0-9]*)(?:/\S+)?(?:\s.*)?$|^\(Subroutine Label\)$")
_BODY_START = ("Purpose", "Format")
_SPECIAL_NAMES = {"\\$": "$", "(Subroutine Label)": "#"}
_TABLE_HEADER = re.compile(r"^Abbr\.\s+Read\s+Write\s+Command")
_LATEX = re.compile(r"\\text\{([^}]*)\}")
_STRUCTURE_WORDS = ("THEN", "DO", "ELSE", "ENDIF", "TO", "STEP", "NEXT", "UNTIL", "ENDW", "ENDL", "USING", "MOD", "~")
"""Words the v3 guide uses inside constructs and expressions without a chapter 10 heading."""


@dataclass(frozen=True)
class V3Entry:
    """One keyword of the v3 guide with the facts read from its entry."""

    name: str
    abbreviation: str | None
    read: bool
    write: bool
    command: bool
    addressing: Addressing
    line: int
    function: bool = False  # called with its argument in brackets: v = PEEK(<expression>)
    formats: tuple[str, ...] = ()  # as its Format section prints them


def _split_name(token: str) -> tuple[str, str | None]:
    name, _, abbreviation = token.partition("/")
    return _SPECIAL_NAMES.get(name, name), abbreviation or None


def _expand(first: str, last: str) -> list[tuple[str, str | None]]:
    """``IN0/IO .. IN7/I7`` -> IN0/I0 ... IN7/I7; ``FOR .. NEXT`` -> FOR only."""
    name, abbreviation = _split_name(first)
    last_name, last_abbreviation = _split_name(last)
    start = re.search(r"\d+$", name)
    stop = re.search(r"\d+$", last_name)
    if not start or not stop:
        return [(name, abbreviation)]
    prefix = name[: start.start()]
    abbreviation_prefix = re.sub(r"\d+$", "", last_abbreviation) if last_abbreviation else None
    return [
        (f"{prefix}{n}", f"{abbreviation_prefix}{n}" if abbreviation_prefix else None)
        for n in range(int(start.group()), int(stop.group()) + 1)
    ]


def heading_keywords(heading: str) -> list[tuple[str, str | None]]:
    """(name, abbreviation) of every keyword a v3 heading names."""
    if heading in _SPECIAL_NAMES:
        return [(_SPECIAL_NAMES[heading], None)]
    text = re.sub(r"\s*\([^)]*\)|\*", "", heading)
    tokens = re.sub(r"(\w)\.\.(\d)", r"\1 .. \2", text).split()
    found: list[tuple[str, str | None]] = []
    index = 0
    while index < len(tokens):
        if index + 2 < len(tokens) and tokens[index + 1] == "..":
            last = tokens[index + 2]
            if last.isdigit():  # "XIO0..7"
                last = re.sub(r"\d+$", last, tokens[index])
            found += _expand(tokens[index], last)
            index += 3
        else:
            found.append(_split_name(tokens[index]))
            index += 1
    return found


def _headings(seed: Seed, start: int, end: int) -> Iterator[tuple[int, str]]:
    for number in range(start, end):
        text = seed.stripped(number)
        if not text or not _HEADING.match(text) or text.startswith(_BODY_START):
            continue
        following = seed.next_nonblank(number)
        if seed.stripped(following).startswith("For use with"):
            following = seed.next_nonblank(following)
        if seed.stripped(following).startswith(_BODY_START):
            yield number, text


def _table_flags(seed: Seed, start: int, end: int) -> tuple[bool, bool, bool] | None:
    """Read/Write/Command ticks of the entry's attribute table, if it has one."""
    for number in range(start, end):
        if _TABLE_HEADER.match(seed.stripped(number)):
            cells = seed.line(seed.next_nonblank(number)).split("\t")
            ticks = ["checkbox" in cell for cell in cells[1:4]] + [False] * 3
            return ticks[0], ticks[1], ticks[2]
    return None


def _returns_value(seed: Seed, start: int, end: int) -> bool:
    """The entry says the keyword returns or reads a value (``To return ...``, ``Return the ...``)."""
    for number in range(start, end):
        text = seed.stripped(number)
        if text.startswith("Purpose"):
            text = seed.stripped(seed.next_nonblank(number))
        if text.startswith(("To return", "To read", "Return the", "Returns the")) and not text.startswith(
            _MOVES_THE_CURSOR
        ):
            return True
    return False


# BOL's "Return the cursor to the Beginning Of Line" (001:6249-6251) moves the cursor: a command, as its
# examples use it (``? POS; : BOL``, 001:2289, 6256), not a keyword that returns a value
_MOVES_THE_CURSOR = "Return the cursor"


_PROSE = re.compile(r"(?:\S+\s+){7,}\S*\.(?:\s|$)")
"""A sentence: the description the guide prints under a format without its heading (AUTO, 001:5833)."""


def _format_lines(seed: Seed, start: int, end: int) -> tuple[str, ...]:
    """The Format section's lines: up to the table, the example, a sentence, or the end of its fenced block
    (WHILE's description follows the fence, 001:12570-12575)."""
    lines: list[str] = []
    inside = fenced = closed = False
    for number in range(start, end):
        raw = seed.stripped(number)
        text = _LATEX.sub(r"\1", raw).strip("` ").replace("*", "")
        if len(text) > 1 and text[0] == text[-1] == "$":  # LaTeX's $v = XOUT[bank]$ (001:12795), not $<card>
            text = text[1:-1].strip()
        if text.startswith("Format:") or text == "Format":  # RAMP's heading has no colon (001:11204)
            inside = True
        elif not inside or not raw:
            continue
        elif _TABLE_HEADER.match(text) or text.startswith(("Example", "See also")) or _PROSE.search(text):
            break
        elif raw.startswith("```"):
            fenced, closed = not fenced, fenced
        elif closed:
            break
        elif text:
            lines.append(text)
    return fmt.clean_formats(lines)


_ABBREVIATED_IN_TEXT = re.compile(r"\b([A-Z]+)(\d+) is the abbreviated keyword for ([A-Z]+)\2\b")


def _family_abbreviations(
    seed: Seed, start: int, end: int, keywords: list[tuple[str, str | None]]
) -> list[tuple[str, str | None]]:
    """Abbreviate a family the heading prints bare from its text: ``XIO0..7`` has ``X0..X7``
    because the entry says "X2 is the abbreviated keyword for XIO2" (v3:12753)."""
    for number in range(start, end):
        found = _ABBREVIATED_IN_TEXT.search(seed.stripped(number))
        if found is not None:
            short, family = found[1], found[3]
            return [
                (name, f"{short}{name[len(family) :]}")
                if abbreviation is None and re.fullmatch(rf"{family}\d+", name)
                else (name, abbreviation)
                for name, abbreviation in keywords
            ]
    return keywords


def _entry_records(seed: Seed, line: int, end: int, heading: str) -> list[V3Entry]:
    keywords = _family_abbreviations(seed, line, end, heading_keywords(heading))
    names = tuple(name for name, _ in keywords)
    formats = _format_lines(seed, line, end)
    flags = _table_flags(seed, line, end)
    if flags is None:
        read = _returns_value(seed, line, end) or fmt.reads_keyword(names, formats) or fmt.is_function(names, formats)
        write = fmt.writes_keyword(names, formats)
        flags = (read, write, not (read or write))
    addressing = fmt.addressing(names, formats, [])
    function = _called_with_brackets(names, formats)
    return [V3Entry(name, abbreviation, *flags, addressing, line, function, formats) for name, abbreviation in keywords]


def _called_with_brackets(names: tuple[str, ...], formats: tuple[str, ...]) -> bool:
    """A format calls the keyword with a bracketed argument and never assigns to it: ``v =
    PEEK(<expression>)``, ``PRINT CHR(<expr>)``, ``TAN(<angle>)``."""
    call = re.compile(r"(?:^|=|PRINT)\s*(?:" + "|".join(map(re.escape, names)) + r")\s*\(")
    return any(call.search(f) for f in formats) and not fmt.writes_keyword(names, formats)


def _first_mention(seed: Seed, word: str) -> int:
    """First line of chapter 4 onwards (past the contents) that uses a construct word."""
    chapter4 = seed.find(r"^4\. MINT Numbers", seed.find(r"^4\. MINT Numbers") + 1)
    return seed.find(rf"(?<![\w#]){re.escape(word)}(?!\w)", chapter4)


def v3_entries(seed: Seed) -> list[V3Entry]:
    """Every keyword of v3 chapters 9.3 and 10, plus the construct words."""
    editor = seed.find(r"^9\.3 Editor Commands")
    chapter10 = seed.find(r"^10\. MINT Keywords", editor)
    end = seed.find(r"^11\. ", chapter10)
    headings = list(_headings(seed, editor, end))
    records: list[V3Entry] = []
    for (line, heading), following in zip(headings, [*headings[1:], (end, "")], strict=True):
        records += _entry_records(seed, line, following[0], heading)
    unique: dict[str, V3Entry] = {}
    for record in records:  # IF .. DO and IF .. THEN are one keyword
        unique.setdefault(record.name, record)
    records = list(unique.values())
    named = set(unique)
    for word in _STRUCTURE_WORDS:
        if word not in named:
            abbreviation = "%" if word == "MOD" else None
            records.append(
                V3Entry(word, abbreviation, False, False, False, Addressing.NONE, _first_mention(seed, word))
            )
    return records
