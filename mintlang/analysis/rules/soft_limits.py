"""A reverse software limit set at or above the forward one on the same axis (W119).

SOFTLIMITREVERSE's restriction is that it be less than SOFTLIMITFORWARD (000:16000);
the guide gives no error number for breaking it, so the toolchain warns. Only what is
certain is reported: each keyword written once on the axis, with a constant on a constant
axis, or on the AXES default while nothing writes AXES. Both limits are scaled by the same
factor, which is always positive (000:536-537), so their order in user units is their order
in counts unless SCALE changes between them: a program that writes SCALE more than once is
not checked.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterator

from mintlang.analysis.findings import Finding, own
from mintlang.analysis.traversal import Facts, KeywordUse, Use
from mintlang.records import record
from mintlang.semantic.constants import constant_integer, constant_value
from mintlang.syntax import nodes as n

_FORWARD, _REVERSE = "SOFTLIMITFORWARD", "SOFTLIMITREVERSE"


@record
class _Limit:
    """One limit written on one axis: its constant value (None when not constant) and where."""

    use: KeywordUse
    line: n.PlacedLine
    value: n.Expression | None
    number: float | None


def _axis_values(
    use: KeywordUse, statement: n.KeywordStatement, default: range | None
) -> list[tuple[int | None, n.Expression | None]] | None:
    """(axis, value) for each axis the write gives a value, a trailing ';' giving the last to the axes left
    (000:656-660); the axes are the ``default`` ones when none are written (000:617-639), None if unknown."""
    selector, values = use.keyword.selector, statement.values or ()
    if selector is not None:
        axes: list[int | None] = [constant_integer(axis) for axis in selector.axes]
    elif default is not None:
        axes = list(default)
    else:
        return None
    if statement.fill and values:
        values = (*values, *[values[-1]] * (len(axes) - len(values)))
    return list(zip(axes, values, strict=False))


def _default_axes(facts: Facts) -> range | None:
    """The AXES default while the program and its configuration write no AXES: every axis (000:605-608)."""
    if any(True for _ in facts.statements(n.Axes)):
        return None
    return range(facts.model.controller.axis_count)


def check(facts: Facts) -> Iterator[Finding]:
    if not facts.may_name(_REVERSE):
        return  # no reverse limit written (most programs): no keyword use to walk to
    limits: dict[tuple[str, int], list[_Limit]] = defaultdict(list)
    scale_writes = 0
    default = _default_axes(facts)
    for line, use in facts.keyword_uses():
        if use.use is not Use.WRITE or not isinstance(use.statement, n.KeywordStatement):
            continue
        name = use.keyword.keyword
        scale_writes += name == "SCALE"
        if name not in (_FORWARD, _REVERSE):
            continue
        written = _axis_values(use, use.statement, default)
        if written is None or any(axis is None for axis, _ in written):
            return  # an axis not known before the program runs may be any of them
        for axis, value in written:
            limits[name, axis].append(_Limit(use, line, value, constant_value(value)))
    if scale_writes > 1:
        return
    for (name, axis), reverse in limits.items():
        forward = limits.get((_FORWARD, axis), [])
        if name == _REVERSE and len(reverse) == 1 and len(forward) == 1:
            yield from _compare(axis, reverse[0], forward[0])


def _compare(axis: int, reverse: _Limit, forward: _Limit) -> Iterator[Finding]:
    if reverse.number is None or forward.number is None or reverse.value is None:
        return
    if reverse.number >= forward.number:
        where = f"line {forward.line.number}"
        if forward.use.unit != reverse.use.unit:
            where += f" of the {forward.use.unit}"
        detail = (
            f"the reverse software limit of axis {axis} ({reverse.number:.15g}) is not below its "
            f"forward limit ({forward.number:.15g}, {where}); SOFTLIMITREVERSE must be less than SOFTLIMITFORWARD"
        )
        yield Finding(reverse.use.unit, own("W119", reverse.line.span(reverse.value.span), detail))
