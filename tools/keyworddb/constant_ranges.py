"""Ranges that name a family of constants beside a span: "-1 ≤ x ≤ 11 and relay constant".

DRIVEENABLEOUTPUT and GLOBALERROROUTPUT take an output channel number or one of
the relay constants their entries list (``_RELAY0`` = 1000 ...; 000:9331,
9362-9366, 10981, 11007-11011). A channel is a whole number, so the allowed
values are the span's whole numbers and the family's values; the family is known
only once the constants are, hence this pass after the attributes tables.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import replace

from mintlang.keyworddb.model import Attributes, Constant, Keyword, ValueRange
from tools.keyworddb.attributes import NAMED_CONSTANTS


def _family(word: str, constants: Mapping[str, Constant]) -> tuple[float, ...]:
    """The values of ``_RELAY0``, ``_RELAY1`` ... for ``word`` "relay"."""
    name = re.compile(rf"_{word.upper()}\d+")
    return tuple(sorted(c.value for c in constants.values() if name.fullmatch(c.name)))


def _with_family(keyword: str, limits: ValueRange, constants: Mapping[str, Constant]) -> ValueRange:
    match = NAMED_CONSTANTS.match(limits.text)
    if match is None:
        return limits
    family = _family(match["word"], constants)
    if not family or limits.minimum is None or limits.maximum is None:
        raise ValueError(f"{keyword}: cannot read the range {limits.text!r} as a span and constants")
    span = range(int(limits.minimum), int(limits.maximum) + 1)
    allowed = tuple(sorted({*(float(value) for value in span), *family}))
    return replace(limits, minimum=None, maximum=None, allowed=allowed)


def _row(keyword: str, row: Attributes, constants: Mapping[str, Constant]) -> Attributes:
    return replace(row, range=_with_family(keyword, row.range, constants)) if row.range else row


def with_constant_ranges(keywords: dict[str, Keyword], constants: Mapping[str, Constant]) -> dict[str, Keyword]:
    """Keywords whose ranges name constants, with those constants' values allowed."""
    return {
        name: replace(keyword, attributes=tuple(_row(name, row, constants) for row in keyword.attributes))
        for name, keyword in keywords.items()
    }
