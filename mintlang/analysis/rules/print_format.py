"""USING asking for more digits than PRINT, LINE or INPUT handle (W118).

``PRINT a USING <int>, <frac>`` prints up to 15 integer digits and up to 15
fractional digits, a negative ``<int>`` adding a sign (000:15313-15318); LINE
formats its values as PRINT does (000:13657-13658). ``INPUT a USING <int>, <frac>``
accepts up to 15 integer digits, the sign aside, and up to 3 fractional ones
(000:12247-12249). The guide gives no error number for a larger count, so the
toolchain warns.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.analysis.findings import Finding, own
from mintlang.analysis.traversal import LineScope
from mintlang.semantic.constants import constant_value
from mintlang.syntax import nodes as n

MAX_DIGITS = 15
_PARTS = ("integer", "fractional")
_PRINTED = (MAX_DIGITS, MAX_DIGITS)  # <int>, <frac> of PRINT and LINE
_TYPED = (MAX_DIGITS, 3)  # <int>, <frac> of INPUT


def _using(statement: n.Statement) -> tuple[tuple[n.Expression, ...], tuple[int, int], str]:
    """The USING values of a PRINT, a terminal command that prints (LINE) or an INPUT, their caps, and
    what the controller does with them."""
    if type(statement) is n.Print or type(statement) is n.KeywordStatement:
        return statement.using, _PRINTED, "prints"
    if type(statement) is n.Input:
        return statement.using, _TYPED, "accepts"
    return (), _PRINTED, ""


def each_line(scope: LineScope) -> Iterator[Finding]:
    for statement in scope.facts.statements:
        values, caps, does = _using(statement)
        for part, value, cap in zip(_PARTS, values, caps, strict=False):
            number = constant_value(value, scope.dialect)
            if number is not None and abs(number) > cap:
                detail = f"USING asks for {abs(number):g} {part} digits; the controller {does} at most {cap}"
                yield Finding(scope.unit, own("W118", value.span, detail))
