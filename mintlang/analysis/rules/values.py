"""Constant values written to a keyword, checked against its range (error 3).

For a scaled keyword the printed range applies to the value times the scale
factor (10.2, Attributes), which is not known before run time; but a scale factor is
never negative or zero (000:536-537), so the value's sign is the sign of what the range sees:
``SPEED = -5`` or ``ACCEL = 0`` is out of range whatever the scale. Where every scale factor's table
prints a least value (MintDrive's 1 ≤ x ≤ 65535), a value past the range's far end at that scale is
out of range too: ``SPEED.0 = 8000001`` on MintDrive.
"""

from __future__ import annotations

from collections.abc import Iterator
from functools import cache

from mintlang.analysis.findings import Finding, mint_error
from mintlang.analysis.traversal import KeywordUse, LineScope, Use
from mintlang.controllers import io_banks
from mintlang.dialect import Dialect
from mintlang.keyworddb import database, supplements
from mintlang.keyworddb.model import Controller, Keyword, ValueRange
from mintlang.keyworddb.usage import refusal
from mintlang.semantic.constants import constant_integer, constant_value, held_value
from mintlang.syntax import nodes as n


def each_line(scope: LineScope) -> Iterator[Finding]:
    db = database()
    controller, dialect = scope.controller.controller, scope.dialect
    for use in scope.facts.keyword_uses:
        if use.use is not Use.WRITE or not isinstance(use.statement, n.KeywordStatement):
            continue
        written = db.keywords_of(dialect).get(use.keyword.keyword)
        if written is not None and refusal(written, controller, dialect, Use.WRITE) is not None:
            continue  # not written at all (IDLE, 2000): no value of it is in range, nor out
        if written is not None and written.indices and written.indices[-1] == "bank":
            yield from _output_word(use, scope)
            continue
        name, label = _ranged_as(use.keyword, written, dialect)
        keyword = db.keywords_of(dialect).get(name)
        if name in supplements.ANY_VALUE:
            continue
        # SRAMP's and FOLERRORMODE's too, which print none: the ranges mint-run takes
        attributes = supplements.attributes_for(keyword, controller, dialect) if keyword else None
        # a scale factor is positive whatever its table prints, or where it prints none (ServoNode 51's SCALE)
        positive = name in supplements.POSITIVE_ONLY
        limits = supplements.held_range(name, attributes, controller, dialect)
        if limits is not None and limits.allowed is None and limits.minimum is None and limits.maximum is None:
            limits = None  # TRIGGERMODE's "whole numbers": the whole test below is all there is
        whole = supplements.whole_only(name, dialect)
        if limits is None and not (positive or whole):
            continue
        scaled = attributes is not None and attributes.scaled
        least = _least_scale(controller, dialect) if scaled else 0.0
        for value in use.statement.values or ():
            number = constant_value(value, dialect)
            if value is None or number is None:
                continue
            # Whole-number ranges are enforced for modes only: the manual prints "0 ≤ x ≤ 10000" for
            # KDERIV and then writes KDERIV = 1.5 in its example (supplements.whole_only).
            held = held_value(value, dialect) if whole else None
            if held is not None and not held.is_integer():
                detail = f"{held:.7g} is not a whole number: {label} takes whole numbers only"
                yield Finding(use.unit, mint_error(3, value.span, detail))
            elif positive and number <= 0:
                yield Finding(use.unit, mint_error(3, value.span, f"{label} takes only a positive value"))
            elif limits is not None and not (
                scaled_can_hold(limits, number, least) if scaled else limits.holds(number)
            ):
                detail = f"{_as_written(value, number)} is outside the range of {label} ({limits.text})"
                if scaled:
                    detail += " whatever the scale factor" + (f" (at least {least:g})" if least else "")
                yield Finding(use.unit, mint_error(3, value.span, detail))


def _as_written(value: n.Expression, number: float) -> str:
    """The value as a message shows it: a constant by its name too (``_RELAY0 (1000)``), as the line reads it."""
    shown = f"{number:.15g}"
    return f"{value.name} ({shown})" if isinstance(value, n.ConstantRef) else shown


def _ranged_as(ref: n.KeywordRef, keyword: Keyword | None, dialect: Dialect) -> tuple[str, str]:
    """The keyword whose range a write is held to, and how a message names it: its own, or for a MintMT keyword
    whose index writes a v4 one (``CONTOURPARAMETER([0,1],0)``, CONTOURANGLE: ``supplements.INDEXED_AS``)
    that one's, as the run does; or the v4 keyword it writes (``OUTX``, ``supplements.WRITTEN_AS``)."""
    if (written := supplements.WRITTEN_AS.get(ref.keyword)) is not None and dialect is Dialect.MINTMT:
        return written, f"{ref.keyword}, as {written}"
    selector = ref.selector
    if keyword is None or not keyword.indices or selector is None or selector.indices != len(keyword.indices):
        return ref.keyword, ref.keyword
    index = constant_integer(selector.items[-1], dialect)
    found = supplements.INDEXED_AS.get((ref.keyword, index)) if index is not None else None
    return (found, f"{ref.keyword} index {index}, as {found}") if found is not None else (ref.keyword, ref.keyword)


def _output_word(use: KeywordUse, scope: LineScope) -> Iterator[Finding]:
    """A bank's outputs written at once (MintMT's ``MOVEOUT(axis, bank) = pattern``): a whole number, one bit an
    output of the bank, below ``IOBanks.output_words`` as the run holds it (MT-22); else error 3."""
    words = io_banks(scope.controller).output_words
    for value in use.statement.values or ():  # type: ignore[union-attr]
        number = constant_value(value, scope.dialect)
        if value is not None and number is not None and not (number.is_integer() and 0 <= number < words):
            detail = f"{number:.15g}: {use.keyword.keyword} takes a pattern of 0 to {words - 1}, one bit an output"
            yield Finding(use.unit, mint_error(3, value.span, detail))


SCALE_FACTORS = ("SCALE", "ENCODERSCALE", "AUXENCODERSCALE")
"""The factors a scaled keyword's value is multiplied by: an axis's, an encoder's, an auxiliary encoder's."""


@cache
def _least_scale(controller: Controller, dialect: Dialect) -> float:
    """The least scale factor ``controller`` accepts: the smallest printed minimum of ``SCALE_FACTORS``
    (1 on MintDrive: 000:15784, 000:9728, 000:6761); 0 where one prints none or leaves it out (0 < x),
    so that only a factor's sign is known."""
    keywords = database().keywords_of(dialect)
    minima = []
    for name in SCALE_FACTORS:
        keyword = keywords.get(name)
        row = supplements.attributes_for(keyword, controller, dialect) if keyword is not None else None
        found = supplements.narrowed(name, row.range if row is not None else None, controller)
        if found is None or found.minimum is None or not found.minimum_included:
            return 0.0
        minima.append(found.minimum)
    return max(0.0, min(minima))


def scaled_can_hold(limits: ValueRange, value: float, least: float) -> bool:
    """Whether ``value`` times some scale factor of at least ``least`` (any positive one when it is 0) lies in
    ``limits``: a larger factor only takes the product further from zero."""
    if value == 0:
        return limits.holds(0.0)
    nearest = value * least  # the product nearest zero
    if value > 0:
        if limits.maximum is None:
            return True
        return limits.maximum > nearest or (least > 0 and limits.maximum_included and limits.maximum == nearest)
    if limits.minimum is None:
        return True
    return limits.minimum < nearest or (least > 0 and limits.minimum_included and limits.minimum == nearest)
