"""Divisions by a divisor that is zero before the program runs (error 2021, "Divide by zero").

The guide's mathematical operators divide twice: ``/``, and ``MOD`` (also written ``%``), the
remainder of a division (000:1276-1282, 000:14019-14041). A zero divisor stops the program with
#2021 when the line runs (000:19063-19070), and mint-run stops there with the same number. The
divisor is known to be zero when the constant folding the other rules use gives 0, worked out in the
controller's binary32 numbers: ``0``, ``0.0``, ``(0)``, ``-0``, ``(2-2)``, ``(0.1+0.2-0.3)``. A
variable, an element or a keyword's reading (``VEL``) may be zero only while the program runs,
which the guide tells the author to test first (000:19066-19070).
Mint v3's guide lists no such error, so v3 programs are not checked.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.analysis.findings import Finding, mint_error
from mintlang.analysis.traversal import LineScope
from mintlang.semantic.constants import held_value
from mintlang.syntax import nodes as n

_DIVIDING = frozenset({"/", "MOD"})  # the parser reads % as MOD


def each_line(scope: LineScope) -> Iterator[Finding]:
    for division in scope.facts.arithmetic:  # gathered by the walk that indexes the line
        if division.operator in _DIVIDING and held_value(division.right, scope.dialect) == 0:
            detail = _detail(scope.syntax.text, division)
            yield Finding(scope.unit, mint_error(2021, division.right.span, detail))


def _detail(text: str, division: n.Binary) -> str:
    """What divides by what, as written: a macro's expansion is placed at the macro's name."""
    divisor = division.right
    written = text[divisor.span.start : divisor.span.end]
    if division.span == divisor.span:
        return f"{written} expands to a division by zero"
    detail = f"{text[division.span.start : division.span.end]} divides by zero"
    if type(divisor) is not n.Number or written != divisor.text:  # an expression, or a macro
        detail += f": {written} is always 0"
    return detail
