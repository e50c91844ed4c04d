"""The values a keyword accepts on a controller, from the reference guide's attributes tables.

A value outside raises error 3 ("Data specified out of range"), as the
controller does (000:18518-18521); the manual prints ``SCALE = -3`` as its
example (000:4600-4606).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from typing import TypeVar

from mintlang import binary32
from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Controller, ValueRange
from mintlang.keyworddb.supplements import attributes_for, narrowed, whole_only
from mintlang.records import record
from mintlang.runtime.errors import OUT_OF_RANGE, MintError

Number = TypeVar("Number", bound=int | None)  # the axis or channel a write names, as its resolver returns it


@record
class Bounds:
    minimum: float | None
    maximum: float | None
    exclusive_minimum: bool  # ACCEL: 0.0 < x
    allowed: frozenset[float] | None = None  # a mode keyword's values, where they are not a range
    exclusive_maximum: bool = False  # OUT: x < 4096
    whole: bool = False  # a mode keyword's: fractions select no mode (``supplements.whole_only``)


UNBOUNDED = Bounds(None, None, False)


def table_bounds(keyword: str, controller: Controller, dialect: Dialect = Dialect.V4) -> Bounds:
    """The range the keyword's attributes table gives for ``controller``, as its entry's text may narrow it
    (``supplements.narrowed``); unbounded when it gives none. The row is the one ``mint check`` reads
    (``supplements.attributes_for``): a MintMT keyword's is written from ``mintlang/MINTMT.md``'s decisions,
    and an entry that prints no table (an Advanced-guide keyword: MOVEBUFFERSIZE, KACCEL) takes the
    supplement's."""
    record = database().keywords_of(dialect).get(keyword)
    row = attributes_for(record, controller, dialect) if record is not None else None
    found = narrowed(keyword, row.range if row is not None else None, controller)
    bounds = UNBOUNDED if found is None else bounds_of(found)
    return replace(bounds, whole=True) if whole_only(keyword, dialect) else bounds


def bounds_of(found: ValueRange) -> Bounds:
    """The bounds a printed range gives."""
    exclusive_minimum = not found.minimum_included
    allowed = frozenset(found.allowed) if found.allowed is not None else None  # a mode's values: "0 .. 4, 6"
    return Bounds(
        found.minimum, found.maximum, exclusive_minimum, allowed, exclusive_maximum=not found.maximum_included
    )


def table_default(keyword: str, controller: Controller) -> float | None:
    """The power-up value ``keyword``'s attributes table gives for ``controller``; None when it gives no number."""
    record = database().keywords.get(keyword)
    row = record.attributes_for(controller) if record is not None else None
    if row is None or row.default is None:
        return None
    try:
        return float(row.default.replace(",", ""))
    except ValueError:
        return None  # "20,000, 1000 (stepper)": a default per axis type


def as_written(channel: int | None) -> int | None:
    """The channel of a keyword whose writer checks none: one that takes no number (the compiler refuses
    ``IMASK.3``) or ignores the one given."""
    return channel


def ranged(
    keyword: str,
    controller: Controller,
    write_one: Callable[[Number, float], None],
    dialect: Dialect = Dialect.V4,
    *,
    channel: Callable[[int | None], Number] = as_written,  # type: ignore[assignment]
) -> Callable[[int | None, float], None]:
    """``write_one`` for the values ``keyword``'s table accepts on ``controller``; error 3 for the others.

    ``channel`` finds the axis or channel a write names, raising its error (2, 4, 7, 8) when the controller
    lacks it, before the value is looked at: ``mint check`` reports the number after the dot first, so
    ``ADCMODE.12 = 77`` is error 4 on a NextMove PCI, not 3. ``write_one`` gets the number it returns.
    """
    limits = table_bounds(keyword, controller, dialect)

    def write(written: int | None, value: float) -> None:
        number = channel(written)
        write_one(number, check_range(keyword, value, limits, number))

    return write


def check_range(keyword: str, value: float, limits: Bounds, channel: int | None = None, scale: float = 1.0) -> float:
    """``value`` if ``limits`` accept it; error 3 on ``channel`` otherwise, saying what the keyword takes.

    A scaled keyword's range is for the value multiplied by its axis's ``scale`` (000:5648-5649).
    """
    checked = value * scale
    low, high = limits.minimum, limits.maximum
    fraction = limits.whole and value != int(value)  # a mode keyword's value selects no mode
    refused = fraction or (limits.allowed is not None and checked not in limits.allowed)
    too_low = low is not None and (checked <= low if limits.exclusive_minimum else checked < low)
    too_high = high is not None and (checked >= high if limits.exclusive_maximum else checked > high)
    if refused or too_low or too_high:
        written = f"{keyword} = {shown(value)}"
        if scale != 1.0:
            written += f" is {shown(checked)} at SCALE {shown(scale)}"
        raise MintError(OUT_OF_RANGE, channel, f"{written}; it takes {accepted(limits)}")
    return value


def shown(value: float) -> str:
    """A value as the program wrote it (``binary32.shortest``): 8388607.5 past a range's end of 8388607 is not
    shown as 8388608."""
    return binary32.shortest(value)


def accepted(limits: Bounds) -> str:
    """What ``limits`` accept, in words: ``2 to 16777215``, ``more than 0``, ``0, 1, 2, 3 or 5``, ``whole numbers:
    0 to 5``; a range of one value is that value (MASTERCHANNEL on MintDrive: ``0``)."""
    one_value = limits.minimum is not None and limits.minimum == limits.maximum
    if limits.whole and limits.allowed is None and not one_value:
        bounded = accepted(replace(limits, whole=False))
        return f"whole numbers: {bounded}" if bounded else "whole numbers"
    if limits.allowed is not None:
        *others, last = (shown(value) for value in sorted(limits.allowed))
        return f"{', '.join(others)} or {last}" if others else last
    low, high = limits.minimum, limits.maximum
    if low is not None and high is not None and not (limits.exclusive_minimum or limits.exclusive_maximum):
        return shown(low) if low == high else f"{shown(low)} to {shown(high)}"
    bounds = [
        f"{'more than' if limits.exclusive_minimum else 'at least'} {shown(low)}" if low is not None else "",
        f"{'less than' if limits.exclusive_maximum else 'at most'} {shown(high)}" if high is not None else "",
    ]
    return " and ".join(bound for bound in bounds if bound)
