"""Ranges the attributes table defers to the entry's text ("see below", "see table").

Three shapes of text stand in for a printed range in the v4 guide:

- a table of ranges per LOOPTIME (ACCEL, DECEL, ERRORDECEL, HOMESPEED, JOG, SPEED;
  000:6169-6175, 8893-8897, 11616-11620): any row's range may be in force, so it takes their
  widest span (a scaled keyword is checked by sign only, which the rows agree on). The
  sentence above the table names the controllers it holds for, "MintDrive and ServoNode 51",
  whatever the rows say: ACCEL's one row is "All" with NextMove's range, and the others have a
  MintDrive row and none for ServoNode 51;
- a bit mask built from the entry's table of constants (TERMINAL, whose entry calls it a bit mask,
  000:16695-16706): every combination of the documented bits, and nothing above them;
- a table of valid baud rates (SERIALBAUD, 000:15859-15863): the rates each controller's ports
  take, as far as the garbled ticks tell them apart (``baud_rates``); a row is split where its
  controllers take different rates.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from dataclasses import replace

from mintlang.keyworddb.model import Attributes, Constant, Controller, Keyword, ValueRange
from tools.keyworddb.attributes import controllers_of_label, parse_range
from tools.keyworddb.baud_rates import baud_rates
from tools.keyworddb.entries import Entry, EntryKind, v4_entries
from tools.keyworddb.seeds import Seed
from tools.keyworddb.v4_keywords import canonical_name

_DEFERRED = re.compile(r"^see\b", re.IGNORECASE)
_LOOPTIME_SENTENCE = re.compile(r"^On (?P<label>.+?) the range depends upon\b.*\bLOOPTIME\b")
_LOOPTIME_ROW = re.compile(r"^(?P<looptime>500|1000|2000) (?P<range>-?\d.*≤ x ≤ .+)$")


def _lines(entry: Entry, seed: Seed) -> Iterable[str]:
    return (seed.stripped(number) for number in range(entry.line, entry.end + 1))


def _looptime_range(entry: Entry, seed: Seed) -> ValueRange | None:
    matches = [match for line in _lines(entry, seed) if (match := _LOOPTIME_ROW.match(line))]
    rows = [parse_range(match["range"]) for match in matches]
    if not rows or any(row.minimum is None or row.maximum is None for row in rows):
        return None
    low = min(row.minimum for row in rows if row.minimum is not None)
    high = max(row.maximum for row in rows if row.maximum is not None)
    # each row as printed, for the reader: the bounds checked are their widest span
    text = "; ".join(f"{row.text} at LOOPTIME {match['looptime']}" for row, match in zip(rows, matches, strict=True))
    return ValueRange(text, low, high, fractional=any(row.fractional for row in rows))


def _looptime_controllers(keyword: Keyword, entry: Entry, seed: Seed) -> tuple[Controller, ...]:
    """The controllers the sentence introducing the LOOPTIME table names."""
    for line in _lines(entry, seed):
        if match := _LOOPTIME_SENTENCE.match(line):
            return controllers_of_label(match["label"], keyword.controllers)
    return ()


def _looptime_rows(
    rows: tuple[Attributes, ...], named: tuple[Controller, ...], described: ValueRange
) -> list[Attributes]:
    """The rows with the LOOPTIME range for the ``named`` controllers: a row naming others too is split,
    and a named controller no row lists joins the first row given the range."""
    result: list[Attributes] = []
    for row in rows:
        inside = tuple(c for c in row.controllers if c in named)
        outside = tuple(c for c in row.controllers if c not in named)
        if inside and outside:
            result += [replace(row, controllers=outside), replace(row, controllers=inside, range=described)]
        else:
            result.append(replace(row, range=described) if inside or _defers(row) else row)
    uncovered = tuple(c for c in named if not any(c in row.controllers for row in result))
    first = next((index for index, row in enumerate(result) if row.range is described), None)
    if uncovered and first is not None:
        joined = tuple(c for c in Controller if c in result[first].controllers or c in uncovered)
        result[first] = replace(result[first], controllers=joined)
    return result


def _bit_mask_range(keyword: Keyword, entry: Entry, seed: Seed, constants: Mapping[str, Constant]) -> ValueRange | None:
    if not any("bit mask" in line for line in _lines(entry, seed)):
        return None
    values = [int(constants[name].value) for name in keyword.constants if name in constants]
    if not values or any(value <= 0 or value & (value - 1) for value in values):
        return None
    mask = 0
    for value in values:
        mask |= value
    return ValueRange(f"0 ≤ x ≤ {mask}, any mask of the bits {hex(mask)}", 0.0, float(mask), fractional=False)


def _listed(rates: tuple[float, ...]) -> ValueRange:
    return ValueRange(", ".join(f"{rate:.15g}" for rate in rates), None, None, False, allowed=rates)


def _baud_rows(rows: tuple[Attributes, ...], rates: Mapping[Controller, tuple[float, ...]]) -> list[Attributes]:
    """The rows with each controller's baud rates: a row deferring to the table is split by the rates (a
    controller the table's labels do not name takes every rate it lists)."""
    every = tuple(sorted({rate for listed in rates.values() for rate in listed}))
    result: list[Attributes] = []
    for row in rows:
        if not _defers(row):
            result.append(row)
            continue
        taken = {controller: rates.get(controller, every) for controller in row.controllers}
        for listed in dict.fromkeys(taken.values()):
            controllers = tuple(c for c in row.controllers if taken[c] == listed)
            result.append(replace(row, controllers=controllers, range=_listed(listed)))
    return result


def _defers(row: Attributes) -> bool:
    """Whether the row's range is only a pointer to the entry's text."""
    return row.range is not None and _DEFERRED.match(row.range.text) is not None


def _row(row: Attributes, described: ValueRange | None) -> Attributes:
    return replace(row, range=described) if described is not None and _defers(row) else row


def with_described_ranges(
    keywords: dict[str, Keyword], constants: Mapping[str, Constant], seed: Seed
) -> dict[str, Keyword]:
    """Keywords whose attributes table says "see below", with the range their entry's text gives."""
    entries = {canonical_name(e): e for e in v4_entries(seed) if e.kind is EntryKind.FULL}
    result: dict[str, Keyword] = {}
    for name, keyword in keywords.items():
        entry = entries.get(name)
        looptime = _looptime_range(entry, seed) if entry is not None else None
        named = _looptime_controllers(keyword, entry, seed) if entry is not None and looptime is not None else ()
        if looptime is not None and named:
            result[name] = replace(keyword, attributes=tuple(_looptime_rows(keyword.attributes, named, looptime)))
        elif entry is not None and (rates := baud_rates(list(_lines(entry, seed)), keyword.controllers)):
            result[name] = replace(keyword, attributes=tuple(_baud_rows(keyword.attributes, rates)))
        elif entry is not None and any(_defers(row) for row in keyword.attributes):
            described = looptime or _bit_mask_range(keyword, entry, seed, constants)
            result[name] = replace(keyword, attributes=tuple(_row(row, described) for row in keyword.attributes))
        else:
            result[name] = keyword
    return result
