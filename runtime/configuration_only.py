"""What a configuration file holds and the run never runs, said at its place rather than skipped in silence.

A subroutine of the configuration file cannot be called from the program (000:1882, 11170), and an event
handler is such a subroutine (000:1886-1898): the run calls the configuration's handlers while the configuration
runs, never once the program runs (BEHAVIOUR.md, Handlers per file). A handler for an event the program does not
handle itself then stops serving it when the program starts, which a reader of the configuration would not
guess. MintMT's Startup block is the code the controller runs at power-up (004:128-133), in the program; the
notes say nothing of one in a configuration file, and the run does not enter it.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.diagnostics import Span
from mintlang.dialect import Dialect
from mintlang.semantic.blocks import BlockKind
from mintlang.semantic.events import Event, event_of
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n

_HANDLER = (
    "{} is not run once the program runs: a file's handlers serve that file alone (000:1882), and the program"
    " has none for this event"
)
_STARTUP = (
    "the Startup block is not run: the controller starts the program's at power-up (004:128), and nothing says"
    " it runs one in a configuration file"
)


def configuration_only(model: SemanticModel, name: str) -> tuple[str, ...]:
    """A warning for each handler of the configuration file (``name``) the program lacks, and for its MintMT
    Startup block, at its file, line and column, in the file's order."""
    if model.configuration is None:
        return ()
    handled = {event for _, event, _ in _handlers(model, Unit.PROGRAM)}
    found = [
        (span.start, _HANDLER.format(written))
        for span, event, written in _handlers(model, Unit.CONFIGURATION)
        if event not in handled
    ]
    found += [(span.start, _STARTUP) for span, _ in _openers(model, Unit.CONFIGURATION, BlockKind.STARTUP)]
    index = model.configuration.line_index
    return tuple(f"{name}:{(at := index.position(start)).line}:{at.column}: {text}" for start, text in sorted(found))


def _handlers(model: SemanticModel, unit: Unit) -> Iterator[tuple[Span, Event, str]]:
    """Each event handler of ``unit``'s file, a label (``#TIMER``) or a MintMT Event block: where, which event,
    and as written."""
    dialect = model.program.dialect
    for label in model.symbols.labels[unit].values():
        event = event_of(label.name, dialect)
        if event is not None and label.definitions:
            yield label.definitions[0].span, event, f"#{label.definitions[0].spelling}"
    for span, statement in _openers(model, unit, BlockKind.EVENT):
        if isinstance(statement, n.EventBlock) and (event := event_of(statement.name.text, Dialect.MINTMT)):
            yield span, event, f"Event {statement.name.text}"


def _openers(model: SemanticModel, unit: Unit, kind: BlockKind) -> Iterator[tuple[Span, n.Statement]]:
    """The opening statement of each block of ``kind`` in ``unit``'s file, with its span in the file."""
    placed = {line.number: line for line in model.document(unit).placed}
    for block in model.structures[unit].blocks:
        if block.kind is kind and (line := placed.get(block.opener.line)) is not None:
            statement = n.flatten_statements(line.syntax.statements)[block.opener.index]
            yield line.span(statement.span), statement
