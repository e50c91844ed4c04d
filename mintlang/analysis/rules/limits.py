"""The controller's table limits (3.9).

Too many variables is 3002, too many labels 3000, too many macros 2015. Its
memory is ``memory``'s, its line length ``line_length``'s. In Mint v4 the
variable stack always holds COMMS and GROUPCOMMS (000:18465-18466), one place
each (000:1058-1059), so a program has two fewer than the stack (000:866-868).
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator

from mintlang.analysis.findings import Finding, mint_error
from mintlang.analysis.traversal import Facts
from mintlang.semantic.symbols import Symbol, Unit

PREDEFINED_ARRAYS = ("COMMS", "GROUPCOMMS")  # on a Mint v4 variable stack whatever is declared (000:18465-18466)


def check(facts: Facts) -> Iterator[Finding]:
    model = facts.model
    controller = model.controller
    symbols = model.symbols
    title = controller.title
    reserved = PREDEFINED_ARRAYS if model.program.dialect.modern else ()
    yield from _over(symbols.variables.values(), controller.max_variables, 3002, "variables", title, reserved=reserved)
    yield from _over(symbols.macros.values(), controller.max_macros, 2015, "macros", title)
    for table in symbols.labels.values():
        yield from _over(table.values(), controller.max_labels, 3000, "labels", title)


def _over(
    symbols: Iterable[Symbol], size: int, code: int, what: str, title: str, *, reserved: tuple[str, ...] = ()
) -> Iterator[Finding]:
    """Report the first definition past a table of ``size`` places, ``reserved`` taken, in compile order."""
    definitions = sorted(
        (symbol.definitions[0] for symbol in symbols if symbol.definitions),
        key=lambda occurrence: (occurrence.unit is not Unit.CONFIGURATION, occurrence.span.start),
    )
    limit = size - len(reserved)
    if len(definitions) > limit:
        extra = definitions[limit]
        holds = f"{title} holds {size}" + (f", {len(reserved)} of them {' and '.join(reserved)}" if reserved else "")
        yield Finding(extra.unit, mint_error(code, extra.span, f"{len(definitions)} {what} defined; {holds}"))
