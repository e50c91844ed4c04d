"""The controller's Mint user memory and configuration buffer (9.1): error 3003.

The arrays (four bytes an element) and the compiled code (about half the
program's size) must fit the Mint user memory, and the configuration file its
buffer. The estimate counts only what is certain, so it errs towards silence.

What the arrays need depends on the declarations alone (``ArrayDemand``), the
rest on the files' lengths, which every keystroke changes: the analyser keeps
the demand while an edit leaves the declarations alone, and checks the lengths
on every version (``findings``), so this is not one of ``RULES``.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.analysis.findings import Finding, mint_error
from mintlang.diagnostics import Span
from mintlang.records import record
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.symbols import SymbolTable, Unit


@record
class ArrayDemand:
    """The bytes the declared arrays take, and where the largest is declared (the error's place)."""

    bytes: int
    largest: tuple[Unit, Span] | None


def demand(symbols: SymbolTable) -> ArrayDemand:
    arrays = [symbol for symbol in symbols.variables.values() if symbol.array_size and symbol.definitions]
    if not arrays:
        return ArrayDemand(0, None)
    largest = max(arrays, key=lambda symbol: symbol.array_size or 0).definitions[0]
    return ArrayDemand(4 * sum(symbol.array_size or 0 for symbol in arrays), (largest.unit, largest.span))


def findings(model: SemanticModel, arrays: ArrayDemand) -> Iterator[Finding]:
    controller = model.controller
    configuration = model.configuration
    if configuration is not None and len(configuration.source) > controller.configuration_buffer:
        detail = (
            f"the configuration file has {len(configuration.source)} characters; "
            f"the buffer of {controller.title} holds {controller.configuration_buffer} bytes"
        )
        yield Finding(Unit.CONFIGURATION, mint_error(3003, Span(0, 0), detail))
    needed = len(model.program.source) // 2 + arrays.bytes
    if arrays.largest is not None and needed > controller.user_memory:
        unit, span = arrays.largest
        detail = (
            f"arrays and compiled code need about {needed // 1024} KB; "
            f"{controller.title} has {controller.user_memory // 1024} KB of Mint user memory"
        )
        yield Finding(unit, mint_error(3003, span, detail))
