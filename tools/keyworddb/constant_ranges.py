"""Ranges that name a family of constants beside a span: "-1 ≤ x ≤ 11 and relay constant".

DRIVEENABLEOUTPUT and GLOBALERROROUTPUT take an output channel number or one of
the relay constants their entries list (``_RELAY0`` = 1000 ...; 000:9331,
9362-9366, 10981, 11007-11011). A channel is a whole number, so the allowed
values are the span's whole numbers and the family's values; the family is known
only once the constants are, hence this pass after the attributes tables. A member
whose table row is marked "(NextMove PCI only)" on the line below (the relays of the
expansion cards, 000:9365, 9368) is allowed on that controller's rows only.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import replace

from mintlang.keyworddb.model import Attributes, Constant, Controller, Keyword, ValueRange
from mintlang.records import record
from tools.keyworddb.attributes import NAMED_CONSTANTS, controllers_of_label
from tools.keyworddb.seeds import Seed

_ONLY = re.compile(r"^\((?P<label>.+) only\)$")


@record
class _Member:
    """A constant of a family, and the controllers its row limits it to (``only``: their label; empty for all)."""

    constant: Constant
    controllers: tuple[Controller, ...]
    only: str


def _family(word: str, constants: Mapping[str, Constant], seed: Seed) -> tuple[_Member, ...]:
    """``_RELAY0``, ``_RELAY1`` ... for ``word`` "relay", by value."""
    name = re.compile(rf"_{word.upper()}\d+")
    members = sorted((c for c in constants.values() if name.fullmatch(c.name)), key=lambda c: c.value)
    return tuple(_member(constant, seed) for constant in members)


def _member(constant: Constant, seed: Seed) -> _Member:
    note = _ONLY.match(seed.stripped(seed.next_nonblank(constant.line)))
    if note is None:
        return _Member(constant, tuple(Controller), "")
    return _Member(constant, controllers_of_label(note["label"], ()), note["label"])


def _with_family(
    keyword: str, limits: ValueRange, controllers: tuple[Controller, ...], constants: Mapping[str, Constant], seed: Seed
) -> ValueRange:
    """``limits`` of a row for ``controllers``, with the family's members those controllers have."""
    match = NAMED_CONSTANTS.match(limits.text)
    if match is None:
        return limits
    family = _family(match["word"], constants, seed)
    if not family or limits.minimum is None or limits.maximum is None:
        raise ValueError(f"{keyword}: cannot read the range {limits.text!r} as a span and constants")
    kept = [member for member in family if set(controllers) <= set(member.controllers)]
    left = [member for member in family if member not in kept]
    if any(set(controllers) & set(member.controllers) for member in left):
        raise ValueError(f"{keyword}: one row names controllers that differ on {left[0].constant.name}")
    span = range(int(limits.minimum), int(limits.maximum) + 1)
    allowed = tuple(sorted({*(float(value) for value in span), *(member.constant.value for member in kept)}))
    notes = {member.only: [m.constant.name for m in left if m.only == member.only] for member in left}
    text = limits.text + "".join(f"; {', '.join(names)}: {label} only" for label, names in notes.items())
    return replace(limits, text=text, minimum=None, maximum=None, allowed=allowed)


def _row(keyword: str, row: Attributes, constants: Mapping[str, Constant], seed: Seed) -> Attributes:
    if row.range is None:
        return row
    return replace(row, range=_with_family(keyword, row.range, row.controllers, constants, seed))


def with_constant_ranges(
    keywords: dict[str, Keyword], constants: Mapping[str, Constant], seed: Seed
) -> dict[str, Keyword]:
    """Keywords whose ranges name constants, with those constants' values allowed where their rows' controllers
    have them."""
    return {
        name: replace(keyword, attributes=tuple(_row(name, row, constants, seed) for row in keyword.attributes))
        for name, keyword in keywords.items()
    }
