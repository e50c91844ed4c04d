"""Sums, differences, products and quotients of constants too large for a Mint number (error 3).

A number has an 8-bit exponent and a 24-bit mantissa (000:714-716), so the largest it holds is about
3.40282e38: ``16777215 * 16777215 * ...`` seven times, or the largest number plus itself, has no value.
mint-run stops the line with #3, "Data specified out of range" (000:18518-18521), as it does for an
EXP or POW too large (the function-domains rule) and a literal too large (the lexer); the guide names
no other error for it (runtime/BEHAVIOUR.md, NM-1). Each operand's value is worked out as the
controller holds it (``held_value``), so the operation reported is the first one too large: the
operations that contain it have no value either, and a variable's value is known only when it runs.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang import binary32
from mintlang.analysis.findings import Finding, mint_error
from mintlang.analysis.traversal import LineScope
from mintlang.diagnostics import quoted
from mintlang.semantic.constants import binary_value, held_value


def each_line(scope: LineScope) -> Iterator[Finding]:
    for operation in scope.facts.arithmetic:  # gathered by the walk that indexes the line
        left = held_value(operation.left, scope.dialect)
        right = held_value(operation.right, scope.dialect) if left is not None else None
        if right is None:
            continue
        value = binary_value(operation.operator, left, right)  # type: ignore[arg-type]
        if value is None:
            continue  # a division by zero: the zero-divisors rule's error 2021
        try:
            binary32.rounded(value)
        except OverflowError:
            span = operation.span
            detail = f"{quoted(scope.syntax.text[span.start : span.end])} is too large for a Mint number"
            yield Finding(scope.unit, mint_error(3, span, detail))
