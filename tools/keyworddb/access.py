"""Cross-check a keyword's access: attribute table, Format lines and the access error examples.

The attribute tables lose ticks in the PDF text (a row with one tick under
columns that cannot be told apart), while the Format lines are plain text:
when a keyword's formats show a read (``v = RELAY.channel``) or a write the
table does not allow, the formats are followed, unless the entry's own text
says otherwise (IDLE "returns" whether an axis is idle: its write format is a
misprint). Chapter 12 illustrates "Read only or Command" and "Write only" with a
keyword; when that keyword's own entry says otherwise the error example wins:
it is the guide's explicit statement of how the controller rejects the keyword
(ACCELTIME: the table and formats allow reads, the #2002 example says it is
write only). Every such disagreement is recorded as a conflict.
"""

from __future__ import annotations

import re
from dataclasses import replace

from mintlang.keyworddb.model import ErrorCode, Keyword
from tools.keyworddb.conflicts import Conflict, conflict
from tools.keyworddb.seeds import Seed

_FORBIDDEN_ACCESS = {2000: ("write", "written"), 2002: ("read", "read")}
"""Error code -> the ``Attributes`` flag its example says the keyword lacks, and its participle."""
_EXAMPLE = re.compile(r"^e\.g\.\s+(?P<code>.+)$")
_WORD = re.compile(r"\b[A-Z][A-Z0-9]+\b")


_READ_FORMAT = re.compile(r"^\w+ = (?P<word>#?[A-Z][A-Z0-9]*)\b")
_TABLE_FOLLOWED = {"IDLE": "the entry says IDLE returns whether the axis is idle: the write format is a misprint"}
"""Keywords whose formats show an access their entry's text rules out, and why the table is followed."""


def _format_access(keyword: Keyword) -> tuple[bool, bool]:
    """Whether the formats show the keyword read (``v = NAME``) and written (``NAME... = ...``)."""
    reads = any((m := _READ_FORMAT.match(f)) is not None and m["word"] == keyword.name for f in keyword.formats)
    writes = any(f.startswith(keyword.name) and "=" in f for f in keyword.formats)
    return reads, writes


def apply_format_access(keywords: dict[str, Keyword]) -> tuple[dict[str, Keyword], list[Conflict]]:
    """Keywords with the reads and writes their formats show, and the conflicts with their tables."""
    found = []
    updated = dict(keywords)
    for name, keyword in sorted(keywords.items()):
        if not keyword.attributes:
            continue
        reads, writes = _format_access(keyword)
        missing = [access for access, shown in (("read", reads), ("write", writes)) if shown]
        missing = [access for access in missing if not any(getattr(row, access) for row in keyword.attributes)]
        if not missing:
            continue
        shown = " and ".join(f"{access}s" for access in missing)
        if name in _TABLE_FOLLOWED:
            decision = f"the table is followed: {_TABLE_FOLLOWED[name]}"
        else:
            decision = "the formats are followed"
            rows = tuple(replace(row, **dict.fromkeys(missing, True)) for row in keyword.attributes)
            updated[name] = replace(keyword, attributes=rows)
        detail = f"{name}: its formats show {shown}, its attributes table (line {keyword.line}) does not; {decision}"
        found.append(conflict("access_format", name, detail, (keyword.line,), keywords=[name]))
    return updated, found


def _example(seed: Seed, error: ErrorCode) -> tuple[int, str] | None:
    number = seed.next_nonblank(seed.next_nonblank(error.line))
    match = _EXAMPLE.match(seed.stripped(number))
    return (number, match["code"]) if match else None


def apply_access_examples(
    seed: Seed, errors: dict[int, ErrorCode], keywords: dict[str, Keyword]
) -> tuple[dict[str, Keyword], list[Conflict]]:
    """Keywords with the access the error examples show, and the conflicts this settles."""
    found = []
    updated = dict(keywords)
    for code, (access, participle) in sorted(_FORBIDDEN_ACCESS.items()):
        example = _example(seed, errors[code])
        if example is None:
            continue
        number, text = example
        for word in _WORD.findall(text):
            keyword = updated.get(word)
            if keyword is None or not keyword.attributes:
                continue
            if any(getattr(row, access) for row in keyword.attributes):
                detail = (
                    f"{word}: its attributes table (entry line {keyword.line}) allows {access}s, but the example "
                    f"of error #{code} '{errors[code].title}' (line {number}) says it cannot be {participle}; "
                    "the error example is followed"
                )
                found.append(conflict("access", word, detail, (keyword.line, number), keywords=[word]))
                rows = tuple(replace(row, **{access: False}) for row in keyword.attributes)
                updated[word] = replace(keyword, attributes=rows)
    return updated, found
