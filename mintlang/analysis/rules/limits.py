"""The controller's table limits (3.9).

Too many variables is 3002, too many labels 3000, too many macros 2015. Its
memory is ``memory``'s, its line length ``line_length``'s.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator

from mintlang.analysis.findings import Finding, mint_error
from mintlang.analysis.traversal import Facts
from mintlang.semantic.symbols import Symbol, Unit


def check(facts: Facts) -> Iterator[Finding]:
    model = facts.model
    controller = model.controller
    symbols = model.symbols
    yield from _over(symbols.variables.values(), controller.max_variables, 3002, "variables", controller.title)
    yield from _over(symbols.macros.values(), controller.max_macros, 2015, "macros", controller.title)
    for table in symbols.labels.values():
        yield from _over(table.values(), controller.max_labels, 3000, "labels", controller.title)


def _over(symbols: Iterable[Symbol], limit: int, code: int, what: str, title: str) -> Iterator[Finding]:
    """Report the first definition past the limit, in compile order."""
    definitions = sorted(
        (symbol.definitions[0] for symbol in symbols if symbol.definitions),
        key=lambda occurrence: (occurrence.unit is not Unit.CONFIGURATION, occurrence.span.start),
    )
    if len(definitions) > limit:
        extra = definitions[limit]
        yield Finding(
            extra.unit, mint_error(code, extra.span, f"{len(definitions)} {what} defined; {title} holds {limit}")
        )
