"""USING asking PRINT or LINE for more than the 15 digits the controller prints (W118).

``PRINT a USING <int>, <frac>`` prints up to 15 integer digits and up to 15
fractional digits, a negative ``<int>`` adding a sign (000:15313-15318); LINE
formats its values as PRINT does (000:13657-13658). The guide gives no error
number for a larger count, so the toolchain warns. INPUT's USING states no such
limit (000:12224-12232) and is not checked.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.analysis.findings import Finding, own
from mintlang.analysis.traversal import LineScope
from mintlang.semantic.constants import constant_value
from mintlang.syntax import nodes as n

MAX_DIGITS = 15
_PARTS = ("integer", "fractional")


def _using(statement: n.Statement) -> tuple[n.Expression, ...]:
    """The USING values of a PRINT, or of a terminal command that prints (LINE)."""
    return statement.using if type(statement) is n.Print or type(statement) is n.KeywordStatement else ()


def each_line(scope: LineScope) -> Iterator[Finding]:
    for statement in scope.facts.statements:
        for part, value in zip(_PARTS, _using(statement), strict=False):
            number = constant_value(value, scope.dialect)
            if number is not None and abs(number) > MAX_DIGITS:
                detail = f"USING asks for {abs(number):g} {part} digits; the controller prints at most {MAX_DIGITS}"
                yield Finding(scope.unit, own("W118", value.span, detail))
