"""S-PROLOGUE: the I/O assignments v3 hardware made and v4 leaves to the program.

v3 controllers had a dedicated limit input per axis (one for both directions,
v3:4600), home and stop inputs and an amplifier enable; v4 user I/O has no
default assignments (v4:4058-4061) and a move on a disabled drive fails with
error 40 (v4:2704-2713). Which pin is which is wiring, so nothing is guessed:
the spec's ``= ?`` placeholders would stop the file compiling, so instead each
missing assignment becomes a ``REM MIGRATE:`` line at the top of the application
carrying the exact v4 statement with an ``<input>``/``<output>`` to fill in. Only
what the program needs is listed: moves need the drive enable, the limits and the stop
input (v3's halted all motion, v3:4544), HOME needs HOMEINPUT, and a #STOP handler or the
stop switch needs STOPINPUT even without a move.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

from mintlang.dialect import Dialect
from mintlang.migrate.context import LABEL, Context, per_pass
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.addressed import MOVES, axis_list, moved_axes, on_target, read_axes, writes_any
from mintlang.migrate.rules.axes import default_axes, selector_axes
from mintlang.migrate.rules.base import Action, Rule, keyword_refs
from mintlang.migrate.rules.notes import prologue_notes
from mintlang.records import record
from mintlang.semantic.events import EventKind, event_of
from mintlang.syntax.nodes import identity


@record
class Assignment:
    """One v4 statement the hardware did for v3, and which axes of a program need it."""

    statement: str  # with {axes} for the axis list
    written_as: frozenset[str]  # keywords whose write means the program already does it
    axes: Callable[[Context], tuple[int, ...] | None]  # the axes needing it; () none, None unknown
    why: str
    done_by: frozenset[str] = frozenset()  # commands that do it too (v4 RESET enables the drive)

    def done(self, context: Context) -> bool:
        return writes_any(context, self.written_as) or next(keyword_refs(context, *self.done_by), None) is not None


def _moving(context: Context) -> tuple[int, ...] | None:
    return moved_axes(context, MOVES)


def _limited(context: Context) -> tuple[int, ...] | None:
    """The moved axes, or those whose limit switches the program only reads or handles: with no
    input assigned v4's LIMIT reads 0 and no limit error ever happens (v4:13321-13332)."""
    moved = _moving(context)
    if moved != ():
        return moved
    axes: set[int] = set()
    for file, line, statement, keyword in keyword_refs(context, *_LIMIT_WORDS):
        named = selector_axes(keyword)
        if named is None and keyword.selector is None:
            default = default_axes(context, file, line.origin + statement.span.start)
            named = default[:1] if default and keyword.keyword.startswith("LIMIT") else default  # a read: the first
        if named is None:
            return None
        axes.update(named)
    return tuple(sorted(axes))


_LIMIT_WORDS = ("LIMIT", "LIMITFORWARD", "LIMITREVERSE", "DISLIMIT", "ENLIMIT")


def _homing(context: Context) -> tuple[int, ...] | None:
    """The axes HOME moves and those whose home switch is read (reading HOME gives the switch's state,
    v3:3509, and S-READ writes it as HOMESWITCH; a bare read is the first default axis, v3:1127); all of
    them when one cannot be known."""
    moved, read = moved_axes(context, ("HOME",)), read_axes(context, ("HOME", "HOMESWITCH"))
    return None if moved is None or read is None else tuple(sorted({*moved, *read}))


def _stopping(context: Context) -> tuple[int, ...] | None:
    """The moved axes: v3's stop input halted all motion whatever the program said (v3:751-758,
    v3:4544-4546); and all axes, when none moves, if the program has a #STOP handler, reads the
    stop switch or sets its mode."""
    moved = _moving(context)
    if moved != ():
        return moved
    handler = any(
        event is not None and event.kind is EventKind.STOP
        for _, line in context.placed(LABEL)
        for event in [event_of(line.syntax.label.text, Dialect.V3) if line.syntax.label is not None else None]
    )
    if not handler and not _mentions(context, frozenset({"STOPSW", "STOPSWITCH", "STOPMODE", "STOPINPUTMODE"})):
        return ()
    return None


def _mentions(context: Context, names: frozenset[str]) -> bool:
    """Any use of ``names``, as a v3 keyword or as a v4 keyword the v3 reader takes for a name
    (by its first ten characters: ``STOPINPUTMODE`` is the name ``STOPINPUTM``)."""
    if next(keyword_refs(context, *names), None) is not None:
        return True
    return not frozenset(map(identity, names)).isdisjoint(_user_names(context))


@per_pass
def _user_names(context: Context) -> frozenset[str]:
    """The identity of every user name the application declares, writes or reads."""
    return frozenset(event.name.identity for _, _, facts in context.model.lines for event in facts.names)


ASSIGNMENTS: tuple[Assignment, ...] = (
    Assignment(
        "DRIVEENABLEOUTPUT{axes} = <output>;",
        frozenset({"DRIVEENABLEOUTPUT"}),
        _moving,
        "v3 amplifier enable was dedicated; -1 if none is wired",
    ),
    Assignment(
        "DRIVEENABLE{axes} = 1;",
        frozenset({"DRIVEENABLE"}),
        _moving,
        "before the first move (after CONFIG); v4 error 40 otherwise",
        frozenset({"RESET"}),
    ),
    Assignment(
        "LIMITFORWARDINPUT{axes} = <input>;",
        frozenset({"LIMITFORWARDINPUT"}),
        _limited,
        "v3 had one limit input per axis for both directions",
    ),
    Assignment(
        "LIMITREVERSEINPUT{axes} = <input>;",
        frozenset({"LIMITREVERSEINPUT"}),
        _limited,
        "the same input as forward if wired as in v3",
    ),
    Assignment(
        "HOMEINPUT{axes} = <input>;", frozenset({"HOMEINPUT", "HMINPUT"}), _homing, "v3 home input was dedicated"
    ),
    Assignment("STOPINPUT{axes} = <input>;", frozenset({"STOPINPUT"}), _stopping, "v3 had a stop input"),
)


class IoPrologue(Rule):
    """Lists the v4 I/O assignments the program needs and does not make, as comments carrying
    the statement to complete, at the top of the configuration file (or program)."""

    id = "S-PROLOGUE"
    rule_class = RuleClass.MANUAL
    phase = Phase.MANUAL
    summary = "moves/HOME/#STOP without v4 I/O assignments -> REM MIGRATE lines with the statements to fill in"
    evidence = "spec S-PROLOGUE; v3:4600, v3:2508-2521; v4:4058-4061, v4:2704-2713, v4:15624-15629"
    notes = True

    def apply(self, context: Context) -> Iterator[Action]:
        notes = []
        for assignment in ASSIGNMENTS:
            axes = assignment.axes(context)
            if axes == () or assignment.done(context):
                continue
            listed = axis_list(on_target(context, axes))
            notes.append(f"{assignment.statement.format(axes=listed)} : REM {assignment.why}")
        yield from prologue_notes(context, self.id, notes)
