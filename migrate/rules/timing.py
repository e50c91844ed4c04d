"""X-GO-TIMING: statements that v3's blocking GO delayed run earlier in v4.

v3 buffers one move per axis: a GO on an axis whose previous move is still
running waits for it to end, so the statement after that GO runs when the
previous segment finishes (v3:3405-3412); the v3 guide places OUT statements
one FLY segment late on purpose (v3:4146-4158, v3:8052-8062). v4 buffers more
moves and GO never waits (v4:2938-2944, v4:11080-11089). Flagged: after a GO
that follows an earlier GO on a shared axis with no PAUSE IDLE between them (in
text order; a label starts afresh), the first statement with an effect outside
the program (an output, the relay, a DAC, the terminal, the comms array, a
subroutine) before the next move, GO or PAUSE; and ``PAUSE`` on TRIGGER. A loop's body runs
again from the state its end leaves: ``LOOP : MOVER = 10 : GO : OUT1 = 1 : ENDL`` waits at each GO
after the first, so OUT1 is flagged too (its body is read twice, a nested loop's once more). Setting
up the next move (MASTERDISTANCE, SPEED …) is not flagged: it applies to the move
loaded next in both versions (v4:3805-3816). The GO right after an OFFSET or a CAM on its line
is not v3's: those started without one (v3:10402, v3:3893-3897) and S-OFFSET and S-CAM write the
GO v4 needs (v4:14780, v4:3872), at which no v3 run waited. Also flagged: a move loaded on an axis
that is still homing (no PAUSE IDLE since its HOME), which v3's blocking GO
sequenced and v4 refuses with error 10 (v4:11473-11475).
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from itertools import groupby
from operator import itemgetter

from mintlang.migrate.context import LABEL, Context, FileView
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.addressed import MOVES, addressed_axes
from mintlang.migrate.rules.base import Action, Rule
from mintlang.records import record
from mintlang.semantic.blocks import LOOPS, closer_kind, opener_kind
from mintlang.syntax import nodes as n

_DELAYED = "v3 ran this when the previous move ended (GO waited); v4 GO does not wait: use PAUSE or MOVEBUFFERFREE"
_TRIGGER = "PAUSE on TRIGGER relied on v3's one-move buffer; v4 buffers more moves (MOVEBUFFERFREE)"
_HOMING = "v3 GO waited for the datum; v4 loads no move while the axis homes (error 10): PAUSE IDLE first"


Running = frozenset[int] | None  # axes with a move started since the last wait; None: not known
_IDLE: Running = frozenset()


def _overlaps(running: Running, axes: tuple[int, ...] | None) -> bool:
    if running == _IDLE:
        return False
    return running is None or axes is None or not running.isdisjoint(axes)


def _started(running: Running, axes: tuple[int, ...] | None) -> Running:
    return None if running is None or axes is None else running | frozenset(axes)


class GoTiming(Rule):
    """Flags what a blocking v3 GO delayed, and PAUSE on TRIGGER."""

    id = "X-GO-TIMING"
    rule_class = RuleClass.MANUAL
    phase = Phase.MANUAL
    summary = "statement after a GO that v3 delayed, PAUSE on TRIGGER -> manual (v4 GO never waits)"
    evidence = "spec X-GO-TIMING; v3:3405-3412, v3:4146-4158, v3:8052-8062; v4:2938-2944, v4:11080-11089"

    def apply(self, context: Context) -> Iterator[Action]:
        """Only the lines that can change the state or show do: the others pass it on. They are
        read as parsed (``line.span`` places a statement): most of a program is timed."""
        outputs = context.mentioned(lambda name: name.startswith("OUT") and name[3:].isdigit())
        loop_words = (n.For, n.While, n.Until, n.BlockWord)
        timed = context.placed(LABEL, n.Pause, n.Print, n.Jump, "COMMS", "GO", *MOVES, *_EFFECTS, *outputs, *loop_words)
        # read as they come, a file at a time: a list of them held most of a program's lines at once
        for file, lines in groupby(timed, key=itemgetter(0)):
            yield from self._file(context, file, (line for _, line in lines))

    def _file(self, context: Context, file: FileView, lines: Iterable[n.PlacedLine]) -> Iterator[Action]:
        state = _Timing()
        loops: list[list[tuple[n.PlacedLine, n.Statement]]] = []  # the statements of each loop open, outermost first
        for line in lines:
            if line.syntax.label is not None:
                state = _Timing()
            for statement in n.walk_statements(line.syntax.statements):
                for body in loops:
                    body.append((line, statement))
                yield from self._statement(context, file, line, statement, state)
                if opener_kind(statement) in LOOPS:
                    loops.append([])
                elif closer_kind(statement) in LOOPS and loops:
                    # the next pass round the loop, from the state this one ends in (the engine writes a marker once)
                    for again, repeated in loops.pop():
                        yield from self._statement(context, file, again, repeated, state)

    def _statement(
        self, context: Context, file: FileView, line: n.PlacedLine, statement: n.Statement, state: _Timing
    ) -> Iterator[Action]:
        start = line.origin + statement.span.start
        loaded, state.loaded = state.loaded, line if _started_without_go(statement) else None
        if loaded is line and _is_go(statement):
            return  # the GO the migration added: v3 ran on at once
        if _moves(statement):
            state.delayed = False
        elif state.delayed and _visible(statement):
            yield self.flag(file, line.span(statement.span), _DELAYED)
            state.delayed = False
        if isinstance(statement, n.KeywordStatement) and statement.keyword.keyword in MOVES:
            axes = addressed_axes(context, file, statement, start)
            if statement.keyword.keyword == "HOME" and statement.values is not None:
                state.homing = _started(state.homing, axes)
            elif _overlaps(state.homing, axes):
                yield self.flag(file, line.span(statement.span), _HOMING)
                state.homing = _IDLE
        if isinstance(statement, n.Pause):
            if _mentions(statement, "TRIGGER"):
                yield self.flag(file, line.span(statement.span), _TRIGGER)
            if _mentions(statement, "IDLE") or _mentions(statement, "HOME"):
                state.running, state.homing = _IDLE, _IDLE
        elif _is_go(statement):
            axes = addressed_axes(context, file, statement, start)
            state.delayed = _overlaps(state.running, axes)
            state.running = _started(state.running, axes)


@record(frozen=False)
class _Timing:
    """What the statements read so far leave: the axes moving and homing, and whether the last GO waited."""

    running: Running = _IDLE
    homing: Running = _IDLE
    delayed: bool = False
    loaded: n.PlacedLine | None = None  # the line whose last statement read started a move v3 ran without GO


def _is_go(statement: n.Statement) -> bool:
    return isinstance(statement, n.KeywordStatement) and statement.keyword.keyword == "GO"


def _started_without_go(statement: n.Statement) -> bool:
    """An OFFSET or a cam written: v3 started it at once (v3:10402, v3:3893-3897)."""
    return (
        isinstance(statement, n.KeywordStatement)
        and statement.keyword.keyword in {"OFFSET", "CAM", "CAMA"}
        and statement.values is not None
    )


def _moves(statement: n.Statement) -> bool:
    """A move set-up, another GO or a wait: its timing is the move's own."""
    if isinstance(statement, n.Pause):
        return True
    return isinstance(statement, n.KeywordStatement) and statement.keyword.keyword in {*MOVES, "GO"}


_EFFECTS = frozenset({"OUT", "RELAY", "DAC", "AUXDAC", "BEEP", "CLS", "LOCATE", "COMMS"})


def _visible(statement: n.Statement) -> bool:
    """Whether the statement acts outside the program, so running it earlier shows."""
    kind = type(statement)
    if kind is n.Print or (kind is n.Jump and statement.word == "GOSUB"):  # type: ignore[union-attr]
        return True
    if kind is n.FunctionStatement:
        return statement.call.function == "COMMS"  # type: ignore[union-attr]
    if kind is not n.KeywordStatement:
        return False
    word = statement.keyword.keyword  # type: ignore[union-attr]
    return word in _EFFECTS or (word.startswith("OUT") and word[3:].isdigit())  # v3's OUT0..OUT7


def _mentions(statement: n.Pause, keyword: str) -> bool:
    return any(
        isinstance(node, n.KeywordRef) and node.keyword == keyword for node in n.walk_expression(statement.condition)
    )
