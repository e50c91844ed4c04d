"""A keyword given one value for several axes in its brackets, with no ';' after it (W122).

The values go to the listed axes in order, and an axis past the last value keeps its own
(000:630-634); a ';' after the last value gives it to every axis left (000:656-659; v3 the same,
001:1109-1113). One value for several listed axes (``DRIVEENABLE[0,1,2] = 1``) is taken for a
missing ';'. Two values or more show their author counting the axes, as the guide's own move on
the first two of three axes does (``MOVEA[0,1,2] = 10,20``, 000:578-581), and are left alone.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.analysis.findings import Finding, own
from mintlang.analysis.rules.addressing import lone_position
from mintlang.analysis.traversal import LineScope
from mintlang.diagnostics import Edit, Fix, Span
from mintlang.keyworddb.model import CIRCLES, VECTORS
from mintlang.syntax import nodes as n

# Moves whose values are one position of all their axes together, one value being the addressing rule's error 2001
_ONE_POSITION = CIRCLES | VECTORS


def _named(text: str, axis: n.Expression) -> str:
    """An axis as the message names it: a number by its digits, which a macro for an axis list (``SF.g1``,
    000:1486-1489) gives where the text has only the macro's name, once for every axis."""
    return axis.text if type(axis) is n.Number else text[axis.span.start : axis.span.end]


def each_line(scope: LineScope) -> Iterator[Finding]:
    text = scope.syntax.text
    for use in scope.facts.keyword_uses:
        keyword, selector = use.keyword, use.keyword.selector
        if selector is None or selector.dot or keyword.keyword in _ONE_POSITION:
            continue
        value = lone_position(use)  # one value, no ';' after it
        if value is None:
            continue
        first, *others = (_named(text, axis) for axis in selector.axes if axis is not None)
        if not others or len(others) + 1 != len(selector.axes):
            continue
        if text[value.span.end :].lstrip().startswith(","):
            continue  # a macro's ':' cut the list after its first value: a syntax error of its own (2003)
        left = (
            f"axis {others[0]} keeps its own"
            if len(others) == 1
            else f"axes {', '.join(others[:-1])} and {others[-1]} keep theirs"
        )
        detail = (
            f"Fewer values than axes listed: {text[keyword.span.start : value.span.end]} sets axis {first} only, "
            f"and {left}; a ';' after the value gives it to every axis listed"
        )
        fix = Fix("Write ';' after the value", (Edit(Span(value.span.end, value.span.end), ";"),), safe=False)
        yield Finding(scope.unit, own("W122", value.span, detail, fixes=(fix,)))
