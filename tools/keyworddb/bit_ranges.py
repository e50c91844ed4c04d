"""Writable bit masks take every combination of the bits their entries document.

CAM's attributes table prints 0 ≤ x ≤ 15, but its entry documents bits 0 to 5
(``_cmTRIGGER`` 16, ``_cmRETRIGGER`` 32, which needs bit 4 set; 000:7563,
7593-7621). CONTOURMODE's prints 0 or 1, but its entry documents bit 1
(``_ctmVECTOR_ANGLE_ON``) and says the mode's valid range is 0 – 3 (000:8567,
8643-8654). A value the entry itself builds from its own constants cannot be out
of range, so such a row's maximum becomes the union of the documented bits, and
each case is recorded as a conflict.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace

from mintlang.keyworddb.model import Attributes, Constant, Keyword, ValueRange
from tools.keyworddb.conflicts import Conflict, conflict
from tools.keyworddb.constants import in_bit_table
from tools.keyworddb.seeds import Seed


def _bits(keyword: Keyword, constants: Mapping[str, Constant], seed: Seed) -> list[Constant]:
    """The keyword's constants that its entry prints in a table of bits."""
    owned = (constants[name] for name in keyword.constants if name in constants)
    return [c for c in owned if c.keyword == keyword.name and in_bit_table(seed, keyword.line, c.line)]


def _widened(row: Attributes, bits: int) -> Attributes:
    """``row`` taking the bits its printed maximum sets and the documented ``bits``, in any combination."""
    limits = row.range
    if not row.write or limits is None or limits.allowed is not None:
        return row
    if limits.minimum is None or limits.maximum is None or limits.maximum != int(limits.maximum):
        return row
    mask = int(limits.maximum) | bits
    if mask == limits.maximum:
        return row
    text = f"{limits.minimum:g} ≤ x ≤ {mask}"
    return replace(row, range=ValueRange(text, limits.minimum, float(mask), fractional=False))


def _keyword(keyword: Keyword, constants: Mapping[str, Constant], seed: Seed) -> tuple[Keyword, list[Conflict]]:
    bits = _bits(keyword, constants, seed)
    mask = 0
    for constant in bits:
        mask |= int(constant.value)
    rows = tuple(_widened(row, mask) for row in keyword.attributes)
    if rows == keyword.attributes:
        return keyword, []
    printed = " / ".join(sorted({row.range.text for row in keyword.attributes if row.range is not None}))
    taken = " / ".join(sorted({row.range.text for row in rows if row.range is not None}))
    detail = (
        f"{keyword.name}: its attributes table (entry line {keyword.line}) prints {printed}, but its entry "
        f"documents the bits {', '.join(c.name for c in bits)}; the bits are followed, in any combination: {taken}"
    )
    lines = (keyword.line, *(c.line for c in bits))
    return replace(keyword, attributes=rows), [
        conflict("bit_range", keyword.name, detail, lines, keywords=[keyword.name])
    ]


def with_bit_ranges(
    keywords: dict[str, Keyword], constants: Mapping[str, Constant], seed: Seed
) -> tuple[dict[str, Keyword], list[Conflict]]:
    """Keywords whose writable range is narrower than their documented bits, widened, with the conflicts."""
    widened: dict[str, Keyword] = {}
    conflicts: list[Conflict] = []
    for name, keyword in keywords.items():
        widened[name], found = _keyword(keyword, constants, seed)
        conflicts += found
    return widened, conflicts
