"""Where a v3 application still runs with the amplifiers off from power-up.

The amplifier enable keeps the amplifiers disabled from power-up until a RESET or CONFIG
(v3:11409-11411), or ENABLE = 1 (v3:7567-7576); ENABLE = 0 leaves them so. The first lines of
the file that runs first (the configuration file, else the program) run once, before any of
those, as long as nothing can take the run back above them after one: no label (a subroutine or
a jump's target), jump or loop before them, no RUN in the application and no event handler in
that file, which can run at any time.
"""

from __future__ import annotations

from mintlang.dialect import Dialect
from mintlang.migrate.context import LABEL, Context, FileView, per_pass, statement_tag
from mintlang.semantic.events import event_of
from mintlang.syntax import nodes as n

_SWITCHING_ON = ("RESET", "CONFIG", "ENABLE")
_LOOPS = frozenset({"LOOP", "REPEAT"})  # the one-word loop openers; FOR and WHILE have nodes of their own


def before_switch_on(context: Context, file: FileView, offset: int) -> bool:
    """Whether the text at ``offset`` of ``file`` runs once, before anything switched the amplifiers on."""
    return file.unit is context.compiled[0].unit and offset < _power_up_end(context)


@per_pass
def _power_up_end(context: Context) -> int:
    """The offset in the first file where the lines that run at power-up end: the first line that
    switches the amplifiers on or can take the run back above it; 0 when none run so."""
    first = context.compiled[0]
    if next(context.placed(statement_tag("RUN")), None) is not None:
        return 0
    ends = [len(first.text)]
    wanted = (LABEL, n.Jump, n.For, n.While, n.BlockWord, *map(statement_tag, _SWITCHING_ON))
    for file, line in context.placed(*wanted):  # as parsed: most lines of a program have one, none needs a copy
        if file.unit is not first.unit:
            continue
        label = line.syntax.label
        if label is not None and event_of(label.text, Dialect.V3) is not None:
            return 0
        if label is not None or any(
            _ends_power_up(statement) for statement in n.flatten_statements(line.syntax.statements)
        ):
            ends.append(line.origin + line.syntax.span.start)
    return min(ends)


def _ends_power_up(statement: n.Statement) -> bool:
    match statement:
        case n.Jump() | n.For() | n.While():
            return True
        case n.BlockWord(word=word):
            return word in _LOOPS
        case n.KeywordStatement(keyword=keyword, values=values):
            return keyword.keyword in _SWITCHING_ON and not (keyword.keyword == "ENABLE" and _off(values))
    return False


def _off(values: tuple[n.Expression | None, ...] | None) -> bool:
    """``ENABLE = 0`` or ``ENABLE = _off``: the enable switched off, which switches nothing on (v3:7567-7576)."""
    match values:
        case (n.Number(value=0.0),) | (n.ConstantRef(name="_OFF"),):
            return True
    return False
