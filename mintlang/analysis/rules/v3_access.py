"""Mint v3 keywords used the way the v3 guide's attribute ticks allow (read, write).

The v3 reading is what mint-migrate starts from: a write to a keyword the v3
guide ticks as read only (``FASTPOS.0 = 5``, 001:7956), a read of one it ticks
as write only (``a = FLY``, "Write only", 001:13073-13080) or a read of a command
(``a = STOP``, "Read only or Command", 001:13083-13094) was already an error on
the v3 controller (2000 / 2002, as v4 numbers them), and so was a parameter written as a
command (``JOG 5``, ``SPEED``): the run stops on it with "No expression" (2005), the v3
guide naming no error of its own for it, so the migrator reports such
a line as broken in v3 already rather than as something the migration broke.
The v3 guide's axis rules are checked here too, for the same reason and so that
mint check finds the "Invalid axis" mint-run raises (001:13173-13184), and the "Missing parameter"
of more values than the axes listed (001:990-992, 13097-13111) or than the three a v3 controller
has at most (001:972), of a vector with a place left empty (001:13100-13109), of a circle not
given its centre and angle (001:6719), and of a second value to a keyword whose format writes one.
A constant written outside the range v3's table prints (``WAIT = 1``, ``GAIN = 300``, ``STOPMODE = 1.5``)
is "Out of range" on the controller, v4's 3 (001:13136-13138), as in mint-run; a scaled one only where no
scale factor brings it in (``SPEED = -5``, ``ACCEL = 0``), SCALE being at least 1 (001:11592).
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import replace

from mintlang.analysis.findings import Finding, mint_error
from mintlang.analysis.rules.addressing import (
    axes_alone,
    circle_values,
    lone_position,
    one_value,
    values_for_axes,
    vector_gap,
)
from mintlang.analysis.rules.values import scaled_can_hold
from mintlang.analysis.traversal import KeywordUse, LineScope, Use
from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import CIRCLES, VECTORS, Addressing, V3Keyword, ValueRange
from mintlang.keyworddb.v3_ranges import AXIS_PARAMETERS, SETTINGS
from mintlang.semantic.constants import constant_integer, constant_value
from mintlang.semantic.symbols import Unit
from mintlang.syntax import nodes as n
from mintlang.syntax.v3_axis_lists import NUMBER_OR_VARIABLE, refused_axes

_MOST_AXES = 3  # "MINT's multi-axis syntax supports up to 3 axes on one controller" (001:972)
_BITS = range(8)  # IN.a and OUT.a: "Out of Range" outside 0 to 7 (001:8965, 10592)
_BIT_WORDS = frozenset({"IN", "OUT"})
_TOO_MANY_VALUES = 2017  # v3's "Missing parameter" for a value no axis takes (001:13097-13104)


def each_line(scope: LineScope) -> Iterator[Finding]:
    for finding in _findings(scope):
        diagnostic = finding.diagnostic
        if diagnostic.mint_error != _TOO_MANY_VALUES:
            yield finding
            continue
        title, _, detail = diagnostic.message.partition(": ")  # v4's title, then the message v3 prints
        message = f"{title}: Missing parameter in Mint v3: {detail}"
        yield replace(finding, diagnostic=replace(diagnostic, message=message))


def _findings(scope: LineScope) -> Iterator[Finding]:
    db = database()
    for statement in scope.facts.statements:
        if isinstance(statement, n.Axes):
            yield from axes_alone(scope.unit, statement)
            if statement.selector is not None:  # AXES[axis list] (001:5967) names axes as the keywords do
                yield from _axis_numbers(scope.unit, statement.selector.items)
    for use in scope.facts.keyword_uses:
        keyword = db.lookup_v3(use.keyword.keyword)
        yield from _axes(use, keyword)
        if keyword is not None and keyword.name in db.v3_one_value_writes:  # OUT.1 = 1, 0
            yield from one_value(use, keyword.name)
        if keyword is not None and use.use is Use.WRITE:
            yield from _out_of_range(use, keyword.name)
        if keyword is None or not keyword.ticked:
            continue  # no attribute ticks to go by
        name, span = keyword.name, use.keyword.spelling_span
        if use.use is Use.WRITE and not keyword.write:
            what = "a command" if keyword.command else "read only"
            yield Finding(use.unit, mint_error(2000, span, f"{name} is {what} in Mint v3 and cannot be given a value"))
        elif use.use is Use.READ and not keyword.read:
            if keyword.command and not keyword.write:  # a = STOP (001:13083-13094)
                yield Finding(use.unit, mint_error(2000, span, f"{name} is a command in Mint v3 and gives no value"))
            else:  # a = FLY (001:13073-13080)
                yield Finding(use.unit, mint_error(2002, span, f"{name} can only be written in Mint v3, not read"))
        elif use.use is Use.COMMAND and not keyword.command:  # JOG 5, SPEED: a parameter is given a value with =
            detail = f"{name} is no command in Mint v3: give it a value with '=' ('{name} = …')"
            yield Finding(use.unit, mint_error(2005, span, detail))


def _axes(use: KeywordUse, keyword: V3Keyword | None) -> Iterator[Finding]:
    """v3's "Invalid axis" (001:13173-13184), as mint-run raises it: an axis list takes only numbers and
    variables (``SF[a+1] = 1000``), and a vector move names two axes or more (``VR[0] = 100``, 001:3257).
    More values than the axes given is v3's "Missing parameter", v4's 2017 (``GAIN[1] = 10,20``,
    001:990-992, 13097-13111), but for a circle's three values on two axes; without brackets the
    default axes are at most the controller's three (001:972)."""
    selector, name = use.keyword.selector, use.keyword.keyword
    if keyword is not None and keyword.addressing is Addressing.AXIS and name not in CIRCLES:
        listed = _MOST_AXES if selector is None else 1 if selector.dot else len(selector.axes)
        yield from values_for_axes(use, listed)
    if name in CIRCLES:
        yield from circle_values(use, name)
    for item in refused_axes(selector) if selector is not None else ():  # None: the default axes, any AXES set
        yield Finding(use.unit, mint_error(2, item.span, f"Invalid axis in Mint v3: {NUMBER_OR_VARIABLE}"))
    if selector is not None and keyword is not None:
        yield from _numbers(use, keyword, selector)
    if name in VECTORS:
        detail = f"Invalid axis in Mint v3: {name} needs two axes or more"
        if selector is not None and len(selector.axes) < 2:
            yield Finding(use.unit, mint_error(2, selector.span, detail))
        elif (position := lone_position(use)) is not None:  # VR[0,1] = 5 or VR = 5: one axis moves, as VR[0]
            yield Finding(use.unit, mint_error(2, position.span, detail))
        else:
            yield from vector_gap(use, name)


def _numbers(use: KeywordUse, keyword: V3Keyword, selector: n.Selector) -> Iterator[Finding]:
    """Constant axis and bit numbers a v3 controller lacks, as the run reports them: an axis past the three
    of 001:972 is "Invalid axis" (v4's 2), an input or output bit outside 0 to 7 "Out of range" (v4's 3)."""
    if keyword.addressing is Addressing.AXIS:
        yield from _axis_numbers(use.unit, selector.items)
    for item in selector.items if keyword.name in _BIT_WORDS else ():
        number = constant_integer(item, Dialect.V3)
        if item is not None and number is not None and number not in _BITS:
            detail = f"Out of range in Mint v3: {keyword.name}.{number}, where the bits are 0 to {_BITS[-1]}"
            yield Finding(use.unit, mint_error(3, item.span, detail))


def _axis_numbers(unit: Unit, items: tuple[n.Expression | None, ...]) -> Iterator[Finding]:
    """Constant axis numbers past the three of 001:972: "Invalid axis" (v4's 2), as the run reports them."""
    for item in items:
        number = constant_integer(item, Dialect.V3)
        if item is not None and number is not None and number not in range(_MOST_AXES):
            detail = f"Invalid axis in Mint v3: axis {number}, where a controller has axes 0 to {_MOST_AXES - 1}"
            yield Finding(unit, mint_error(2, item.span, detail))


def _out_of_range(use: KeywordUse, name: str) -> Iterator[Finding]:
    """Constants written outside the range v3's table prints for ``name``, if it prints one (``v3_ranges``)."""
    row = SETTINGS.get(name) or AXIS_PARAMETERS.get(name)
    if row is None or not isinstance(use.statement, n.KeywordStatement):
        return
    limits = ValueRange(f"{row.lowest:.15g} to {row.highest:.15g}", row.lowest, row.highest, not row.whole)
    for value in use.statement.values or ():
        number = constant_value(value, Dialect.V3)
        if value is None or number is None:
            continue
        if not (scaled_can_hold(limits, number, 1.0) if row.scaled else row.holds(number)):
            detail = f"{number:.15g} is outside the range of {name} in Mint v3 ({limits.text})"
            detail += " whatever the scale factor" if row.scaled else ""
            yield Finding(use.unit, mint_error(3, value.span, detail))
