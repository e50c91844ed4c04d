"""A keyword given nothing after its '=', or PAUSE with no condition (error 2005).

Commas skip axes (``SPEED = ,10`` writes axis 1 only, 000:632-641) and a semicolon repeats
the last value (000:657-663), but in ``SPEED.0 =``, ``SPEED = ,`` or ``COMMS(1) =`` every
place is empty: the keyword is given no value at all. That is #2005, No expression, a keyword
neither read nor assigned a value (000:18930-18934). PAUSE waits for a condition (its format,
000:15023); alone it has none to wait for, which mint-run raises as 2005 too. The error points
where the expression is missing.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.analysis.findings import Finding, mint_error
from mintlang.analysis.traversal import LineScope
from mintlang.diagnostics import Span
from mintlang.syntax import nodes as n


def each_line(scope: LineScope) -> Iterator[Finding]:
    for statement in scope.facts.statements:
        if type(statement) is n.Pause and not scope.dialect.modern:
            continue  # v3's PAUSE alone waits for a key at the terminal (001:2211)
        detail = _missing(statement)
        if detail is not None:
            end = statement.span.end
            yield Finding(scope.unit, mint_error(2005, Span(end, end), detail))


def _missing(statement: n.Statement) -> str | None:
    """What ``statement`` lacks, if it is an expression it needs."""
    kind = type(statement)
    if kind is n.Pause:
        return "PAUSE needs a condition to wait for" if statement.condition is None else None  # type: ignore[union-attr]
    if kind is n.KeywordStatement:
        name = statement.keyword.spelling  # type: ignore[union-attr]
    elif kind is n.FunctionStatement:
        name = f"{statement.call.spelling}(…)"  # type: ignore[union-attr]
    else:
        return None
    values = statement.values  # type: ignore[union-attr]
    if values is not None and all(value is None for value in values):
        return f"{name} is given no value after '='"
    return None
