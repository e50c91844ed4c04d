"""Event handlers: #FASTIN with #FASTINx (error 3006), handlers the controller lacks, two for one event.

A controller calls #INx only for its own digital inputs (Mint v3's for its 8 user inputs), #FASTINx only for
its fast latch inputs, #CAN1/#CAN2 and #COMMS1 .. #COMMS5 only; any other
such label is an ordinary subroutine that nothing calls (3.8.1, 10.3).
In MintMT an ``Event`` block handles an event as such a label does, so both are checked alike (and
only a NextMove raises MOVEBUFFERLOW, 004:109); a ``#`` label for an event a block handles is a
second handler, error 2003 as a second ``Event`` block is (MT-13).
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.analysis.findings import Finding, mint_error, own
from mintlang.analysis.traversal import Facts
from mintlang.controllers import ControllerProfile
from mintlang.diagnostics import Span
from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.records import record
from mintlang.semantic.events import Event, EventKind, event_of
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n

_COMMS = range(1, 6)
_CAN = range(1, 3)
_V3_INPUTS = range(8)  # Mint v3: #IN0 .. #IN7, one for each of the 8 user inputs (001:2523-2527)
_NOT_V3_INPUT = "Mint v3 calls #IN0 to #IN7 only, one for each user input, so this is never called"
_NOT_V3_FASTPOS = "Mint v3 calls #FASTPOS alone, on its one fast interrupt, so this is never called"  # 001:2585


@record
class _Handler:
    """A ``#`` label or a MintMT ``Event`` block (``line`` > 0) for ``event``, named as written."""

    unit: Unit
    written: str
    span: Span
    event: Event
    line: int = 0


def check(facts: Facts) -> Iterator[Finding]:
    model = facts.model
    dialect = model.program.dialect
    labels = [
        _Handler(unit, f"#{symbol.name}", symbol.definitions[0].span, event)
        for unit, symbols in model.symbols.labels.items()
        for symbol in symbols.values()
        if symbol.definitions and (event := event_of(symbol.name, dialect)) is not None
    ]
    blocks = _event_blocks(facts) if dialect is Dialect.MINTMT else []
    handlers = labels + blocks
    for unit in dict.fromkeys(handler.unit for handler in handlers):
        fast = [h for h in handlers if h.unit == unit and h.event.kind is EventKind.FASTIN]
        if any(h.event.number is None for h in fast) and any(h.event.number is not None for h in fast):
            later = max(fast, key=lambda handler: handler.span.start)
            yield Finding(unit, mint_error(3006, later.span, "#FASTIN and #FASTINx handlers cannot both be defined"))
    for handler in handlers:
        problem = unavailable(handler.event, model.controller, dialect)
        if problem is not None:
            yield Finding(handler.unit, own("W109", handler.span, f"{handler.written}: {problem}"))
    first_block: dict[tuple[Unit, Event], int] = {}
    for block in blocks:
        first_block.setdefault((block.unit, block.event), block.line)
    for label in labels:
        line = first_block.get((label.unit, label.event))
        if line is not None:
            detail = f"{label.written} handles the event of the Event block of line {line}: one handler per event"
            yield Finding(label.unit, mint_error(2003, label.span, detail))


def _event_blocks(facts: Facts) -> list[_Handler]:
    """The MintMT ``Event`` blocks that name an event, in each file's order (``Event Comms9`` names none:
    the syntax error 2003 of ``semantic/blocks.py``)."""
    found = []
    for unit, line, statement in facts.statements(n.EventBlock):
        assert isinstance(statement, n.EventBlock)
        name = statement.name
        event = event_of(name.text, Dialect.MINTMT)
        if event is not None and (event.kind is not EventKind.COMMS or event.number in _COMMS):
            found.append(_Handler(unit, f"Event {name.text}", line.span(name.span), event, line.number))
    return found


def unavailable(event: Event, controller: ControllerProfile, dialect: Dialect) -> str | None:
    """Why ``controller`` never calls the handler of ``event`` (the language server's hover says it too), or None."""
    number = event.number
    if event.kind is EventKind.IN and dialect is Dialect.V3:
        return None if number in _V3_INPUTS else _NOT_V3_INPUT
    if event.kind is EventKind.FASTPOS and number is not None:
        return _NOT_V3_FASTPOS
    if event.kind is EventKind.IN and number not in controller.digital_inputs:
        return f"{controller.title} has digital inputs {controller.digital_inputs}, so this handler is never called"
    if event.kind is EventKind.FASTIN and number is not None and number not in controller.fast_inputs:
        inputs = ", ".join(str(x) for x in sorted(controller.fast_inputs))
        return f"{controller.title} calls #FASTINx for x = {inputs} only"
    if event.kind is EventKind.COMMS and number not in _COMMS:
        return "only comms locations 1 to 5 raise an event"
    if event.kind is EventKind.CAN and number not in _CAN:
        return "there are two CAN event handlers, #CAN1 and #CAN2"
    buffer_low = database().mintmt_keywords["MOVEBUFFERLOW"]
    if event.kind is EventKind.MOVEBUFFERLOW and not buffer_low.available_on(controller.controller):
        return f"{controller.title} has no MOVEBUFFERLOW event: the note gives it to NextMove only"
    return None
