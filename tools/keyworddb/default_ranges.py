"""A writable range holds its own default.

AUXENCODERWRAP's attributes table prints 1.0 ≤ x ≤ 8388607.0 on NextMove and 1 ≤ x ≤ 65535
on MintDrive, with a default of 0.0 and 0 (000:6847-6848), and its entry turns the wrap off by
writing that 0.0 (000:6865), as ENCODERWRAP's does with a range from 0 (000:9811, 9825). A value
the controller powers up with, and which the entry tells the reader to write, cannot be out of
range: such a row's bound is moved to take its default, and each case is recorded as a conflict.
"""

from __future__ import annotations

from dataclasses import replace

from mintlang.keyworddb.model import Attributes, Keyword
from tools.keyworddb.conflicts import Conflict, conflict


def _default(row: Attributes) -> float | None:
    try:
        return float(row.default) if row.default else None
    except ValueError:
        return None  # "-", "see below", an axis-dependent default: nothing to compare


def _widened(row: Attributes) -> Attributes:
    """``row`` with its minimum or maximum moved to its default when the default lies outside."""
    limits, default = row.range, _default(row)
    if not row.write or limits is None or default is None or limits.allowed is not None or limits.holds(default):
        return row
    lower, _, upper = limits.text.partition(" x ")
    if limits.minimum is not None and default <= limits.minimum:
        taken = replace(limits, text=f"{row.default} ≤ x {upper}", minimum=default, minimum_included=True)
    else:
        taken = replace(limits, text=f"{lower} x ≤ {row.default}", maximum=default, maximum_included=True)
    return replace(row, range=taken)


def _keyword(keyword: Keyword) -> tuple[Keyword, list[Conflict]]:
    rows = tuple(_widened(row) for row in keyword.attributes)
    if rows == keyword.attributes:
        return keyword, []
    printed = " / ".join(
        f"{row.range.text} (default {row.default})"
        for row, taken in zip(keyword.attributes, rows, strict=True)
        if row.range is not None and taken is not row
    )
    detail = (
        f"{keyword.name}: its attributes table (entry line {keyword.line}) prints {printed}; "
        "the default is a value the controller holds, so the range takes it"
    )
    return replace(keyword, attributes=rows), [
        conflict("default_range", keyword.name, detail, [keyword.line], keywords=[keyword.name])
    ]


def with_default_ranges(keywords: dict[str, Keyword]) -> tuple[dict[str, Keyword], list[Conflict]]:
    """Keywords whose writable range leaves out their own default, widened, with the conflicts."""
    widened: dict[str, Keyword] = {}
    conflicts: list[Conflict] = []
    for name, keyword in keywords.items():
        widened[name], found = _keyword(keyword)
        conflicts += found
    return widened, conflicts
