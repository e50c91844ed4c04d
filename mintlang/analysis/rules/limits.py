"""The controller's table limits (3.9), its memory (9.1) and the 255-character line.

Too many variables is 3002, too many labels 3000, too many macros 2015. Out
of memory is 3003: the arrays (four bytes an element) and the compiled code
(about half the program's size, 9.1) must fit the Mint user memory, and the
configuration file its buffer. The estimate counts only what is certain, so
it errs towards silence.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator

from mintlang.analysis.findings import Finding, mint_error, own
from mintlang.analysis.traversal import Facts
from mintlang.diagnostics import Span
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.symbols import Symbol, Unit


def check(facts: Facts) -> Iterator[Finding]:
    model = facts.model
    controller = model.controller
    symbols = model.symbols
    yield from _over(symbols.variables.values(), controller.max_variables, 3002, "variables", controller.title)
    yield from _over(symbols.macros.values(), controller.max_macros, 2015, "macros", controller.title)
    for table in symbols.labels.values():
        yield from _over(table.values(), controller.max_labels, 3000, "labels", controller.title)
    yield from _memory(model)
    limit = controller.max_line_length
    for unit, document in model.documents():
        for offset, line in document.physical:
            length = line.content_end  # without the line break
            if length > limit:
                detail = f"line has {length} characters; the controller accepts {limit}"
                yield Finding(unit, own("W111", Span(offset + limit, offset + length), detail))


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


def _memory(model: SemanticModel) -> Iterator[Finding]:
    controller = model.controller
    configuration = model.configuration
    if configuration is not None and len(configuration.source) > controller.configuration_buffer:
        detail = (
            f"the configuration file has {len(configuration.source)} characters; "
            f"the buffer of {controller.title} holds {controller.configuration_buffer} bytes"
        )
        yield Finding(Unit.CONFIGURATION, mint_error(3003, Span(0, 0), detail))
    arrays = [symbol for symbol in model.symbols.variables.values() if symbol.array_size and symbol.definitions]
    compiled = len(model.program.source) // 2
    needed = compiled + 4 * sum(symbol.array_size or 0 for symbol in arrays)
    if arrays and needed > controller.user_memory:
        largest = max(arrays, key=lambda symbol: symbol.array_size or 0)
        first = largest.definitions[0]
        detail = (
            f"arrays and compiled code need about {needed // 1024} KB; "
            f"{controller.title} has {controller.user_memory // 1024} KB of Mint user memory"
        )
        yield Finding(first.unit, mint_error(3003, first.span, detail))
