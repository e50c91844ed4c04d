"""Event handlers: #FASTIN with #FASTINx (error 3006), handlers the controller lacks, two for one event.

A controller calls #INx only for its own digital inputs, #FASTINx only for
its fast latch inputs, #CAN1/#CAN2 and #COMMS1 .. #COMMS5 only; any other
such label is an ordinary subroutine that nothing calls (3.8.1, 10.3).
In MintMT an ``Event`` block handles an event too: a ``#`` label for the same
event is a second handler, error 2003 as a second ``Event`` block is (MT-13).
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.analysis.findings import Finding, mint_error, own
from mintlang.analysis.traversal import Facts
from mintlang.controllers import ControllerProfile
from mintlang.dialect import Dialect
from mintlang.semantic.events import Event, EventKind, event_of
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n

_COMMS = range(1, 6)
_CAN = range(1, 3)


def check(facts: Facts) -> Iterator[Finding]:
    model = facts.model
    dialect = model.program.dialect
    blocks = _event_blocks(facts) if dialect is Dialect.MINTMT else {}
    for unit, labels in model.symbols.labels.items():
        handlers = [
            (symbol, event)
            for symbol in labels.values()
            if symbol.definitions and (event := event_of(symbol.name, dialect)) is not None
        ]
        fast = [(symbol, event) for symbol, event in handlers if event.kind is EventKind.FASTIN]
        if any(event.number is None for _, event in fast) and any(event.number is not None for _, event in fast):
            later = max((symbol.definitions[0] for symbol, _ in fast), key=lambda occurrence: occurrence.span.start)
            detail = "#FASTIN and #FASTINx handlers cannot both be defined"
            yield Finding(unit, mint_error(3006, later.span, detail))
        for symbol, event in handlers:
            problem = _unavailable(event, model.controller)
            if problem is not None:
                yield Finding(unit, own("W109", symbol.definitions[0].span, f"#{symbol.name}: {problem}"))
            block = blocks.get((unit, event))
            if block is not None:
                detail = f"#{symbol.name} handles the event of the Event block of line {block}: one handler per event"
                yield Finding(unit, mint_error(2003, symbol.definitions[0].span, detail))


def _event_blocks(facts: Facts) -> dict[tuple[Unit, Event], int]:
    """The line of the first MintMT ``Event`` block of each event, in each file."""
    found: dict[tuple[Unit, Event], int] = {}
    for unit, line, statement in facts.statements(n.EventBlock):
        assert isinstance(statement, n.EventBlock)
        event = event_of(statement.name.text, Dialect.MINTMT)
        if event is not None:
            found.setdefault((unit, event), line.number)
    return found


def _unavailable(event: Event, controller: ControllerProfile) -> str | None:
    number = event.number
    if event.kind is EventKind.IN and number not in controller.digital_inputs:
        return f"{controller.title} has digital inputs {controller.digital_inputs}, so this handler is never called"
    if event.kind is EventKind.FASTIN and number is not None and number not in controller.fast_inputs:
        inputs = ", ".join(str(x) for x in sorted(controller.fast_inputs))
        return f"{controller.title} calls #FASTINx for x = {inputs} only"
    if event.kind is EventKind.COMMS and number not in _COMMS:
        return "only comms locations 1 to 5 raise an event"
    if event.kind is EventKind.CAN and number not in _CAN:
        return "there are two CAN event handlers, #CAN1 and #CAN2"
    return None
