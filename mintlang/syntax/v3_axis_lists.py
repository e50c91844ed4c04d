"""What a Mint v3 axis list in brackets takes: a number or a variable, not an expression or an array element
(``SF[a+1] = 1000``, 001:13173-13184; ``MOVER[a+1]``, 001:1009-1011). ``mint check --dialect v3`` reports the
rest and ``mint-run --dialect v3`` raises it, both as "Invalid axis"."""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.syntax import nodes as n

NUMBER_OR_VARIABLE = "an axis number in brackets must be a number or a variable"


def refused_axes(selector: n.Selector) -> Iterator[n.Expression]:
    """The items of a bracketed axis list that Mint v3 refuses (a dotted one holds an expression by design)."""
    if selector.dot:
        return
    for item in selector.axes:
        if item is not None and not isinstance(item, n.Number | n.VariableRef | n.ConstantRef):
            yield item
