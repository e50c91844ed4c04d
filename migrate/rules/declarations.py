"""Insertions: DIM for v3's implicit variables, the v3 default AXES, input edge modes.

All three go at the top of a file (the migration spec §5): after the ``AUTO``
that must stay first in a configuration file, after the ``PROTECT`` that must
stay first in a program, and otherwise after the comment block that opens the
file, so a header stays a header.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.diagnostics import Span, lines_of
from mintlang.migrate.context import LABEL, MARKER, MARKER_LINE, Context, FileView, marks_above, name_tag, per_pass
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.base import Action, Replace, Rule
from mintlang.migrate.rules.explicit_axes import axis_keyword
from mintlang.migrate.rules.inputs import imask_all_ones, inputs_holding_back_handlers
from mintlang.migrate.rules.remarks import missing_rem_spans
from mintlang.semantic.events import EventKind, event_of
from mintlang.semantic.symbols import Occurrence, Symbol, SymbolKind
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n

V3_DEFAULT_AXES = 3  # power-up AXES[0,1,2] (v3:1029-1033)


def top_of(file: FileView) -> int:
    """Where declarations go: after a leading AUTO (configuration) or PROTECT (program)
    statement and the markers below it that mark it (``marks_above``), else after the
    comment lines the file starts with (a REM MIGRATE line belongs to the line below it,
    so it ends the header)."""
    if file.opening is not None:
        position = _next_line(file, file.opening.span.end)
        for line in file.lines_below(file.opening.span.end):
            found = MARKER_LINE.match(line)
            if found is None or not marks_above(found):
                break
            position = _next_line(file, position)
        return position
    position = 0
    for raw in lines_of(file.text):
        comment = raw.strip().upper()
        if not comment.startswith("REM") or comment.startswith(MARKER):  # a marker belongs to the line below
            break
        position += len(raw)
    return position


def _next_line(file: FileView, offset: int) -> int:
    end = file.line_end(offset)
    return end + len(file.newline) if end < len(file.text) else end


def insert_lines(file: FileView, lines: list[str]) -> Replace:
    """One insertion of whole lines at the top of ``file``, with its own newline: between an
    opening AUTO and the code after it on its line (``AUTO : a = 1``), whose line is broken there,
    or else at ``top_of``."""
    split = file.after_opening
    if split is not None:
        return Replace(file.unit, split, "".join(f"{file.newline}{line}" for line in lines) + file.newline)
    at = top_of(file)
    text = "".join(f"{line}{file.newline}" for line in lines)
    if at == len(file.text) and file.text and not file.text.endswith(("\n", "\r")):
        text = file.newline + text.removesuffix(file.newline)
    return Replace(file.unit, Span(at, at), text)


def prologue_file(context: Context) -> FileView:
    """The configuration file when there is one (it runs first), else the program."""
    return context.files.get(Unit.CONFIGURATION) or context.files[Unit.PROGRAM]


class DeclareVariables(Rule):
    """Every variable v3 declared implicitly (assignment, FOR, INPUT, or a read) gets a bare
    ``DIM name`` at the top of the file that first uses it, in first-use order.

    v4 declares only with DIM, at compile time, before first use in the text; a bare DIM
    keeps an existing value, so the v3 non-volatile idiom still works (a ``DIM x = v``
    would not). A variable of the configuration file is declared there and is visible in
    the program. An array used without a DIM cannot be sized here: manual item.
    """

    id = "M-DIM"
    rule_class = RuleClass.MECHANICAL
    phase = Phase.INSERTIONS
    summary = "implicitly declared v3 variable -> 'DIM name' at the top of the file (first-use order)"
    evidence = "spec M-DIM, §5; v3:1352-1367, v3:1425; v4:897-910, v4:969-970, v4:19073 (#3001)"

    def apply(self, context: Context) -> Iterator[Action]:
        declared = _dimmed(context)
        for unit, file in context.files.items():
            wanted: dict[str, tuple[int, str]] = {}
            visible = declared[unit] | (declared[Unit.CONFIGURATION] if unit is Unit.PROGRAM else set())
            for symbol in context.model.symbols.variables.values():
                if symbol.identity in visible or not _user_name(context, symbol.name):
                    continue  # all of them in the pass confirming this one: the rest is not worked out
                commented = _commented(context)
                uses = [o for o in symbol.occurrences() if o.unit is unit and not _inside(o, commented)]
                if not uses:
                    continue
                if symbol.kind is SymbolKind.ARRAY or symbol.identity in _indexed(context):
                    yield self.flag(file, uses[0].span, f"array '{symbol.name}' is used but never dimensioned")
                    continue
                if unit is Unit.PROGRAM and _first_use_in_configuration(symbol):
                    continue
                first = min(uses, key=lambda o: o.span.start)
                wanted[symbol.identity] = (first.span.start, first.spelling)
            if wanted:
                names = [spelling for _, spelling in sorted(wanted.values())]
                yield insert_lines(file, [f"DIM {name}" for name in names])


@per_pass
def _commented(context: Context) -> list[tuple[Unit, Span]]:
    """The statements that are a comment missing its REM (``STOP following``)."""
    return [(file.unit, span) for file, span in missing_rem_spans(context)]


@per_pass
def _indexed(context: Context) -> frozenset[str]:
    """The identities of the names written with an index anywhere (``name(i)``)."""
    return frozenset(
        event.name.identity for _, _, facts in context.model.lines for event in facts.names if event.element
    )


def _inside(occurrence: Occurrence, spans: list[tuple[Unit, Span]]) -> bool:
    """Whether a name is written in one of ``spans`` (a comment missing its REM declares nothing)."""
    at = occurrence.span
    return any(unit is occurrence.unit and span.start <= at.start and at.end <= span.end for unit, span in spans)


def _user_name(context: Context, name: str) -> bool:
    """Not a constant and not a v4 keyword (migrated text read as v3 shows KPROP as a name)."""
    return not name.startswith("_") and context.db.lookup(name) is None


def _first_use_in_configuration(symbol: Symbol) -> bool:
    first = next(symbol.occurrences(), None)
    return first is not None and first.unit is Unit.CONFIGURATION


def _dimmed(context: Context) -> dict[Unit, set[str]]:
    """Identities each file declares with DIM (scalars and arrays)."""
    found: dict[Unit, set[str]] = {Unit.CONFIGURATION: set(), Unit.PROGRAM: set()}
    for file, line in context.placed(n.Dim):
        for statement in n.flatten_statements(line.syntax.statements):
            if isinstance(statement, n.Dim):
                found[file.unit].add(statement.name.identity)
    return found


class DefaultAxes(Rule):
    """An application that uses the power-up default axes gets ``AXES[0,1,2]``: v3 powered up
    with three default axes, v4 with all the controller's axes, so bracket-less STOP, GO, RESET
    or ``SPEED = …;`` would act on more axes. That is so when an axis keyword is written without
    its axes before any AXES statement (``JOG = 10;`` then ``AXES[0]``), not only when there is
    none. Not needed when the controller has at most three, nor when no axis keyword is written
    without its axes (an empty file, ``OUT.2 = 1``) or every one comes after an AXES: then the
    default decides nothing, and a file already in v4 stays as it is.
    """

    id = "M-AXES"
    rule_class = RuleClass.MECHANICAL
    phase = Phase.INSERTIONS
    summary = (
        "an axis keyword without axes before any AXES -> 'AXES[0,1,2]' first in the configuration file (or program)"
    )
    evidence = "spec M-AXES; v3:1029-1033; v4:605-608, v4:144-182"

    def apply(self, context: Context) -> Iterator[Action]:
        if context.controller.axis_count <= V3_DEFAULT_AXES:
            return
        if not _relies_on_default_axes(context):
            return
        axes = ",".join(str(axis) for axis in range(V3_DEFAULT_AXES))
        yield insert_lines(prologue_file(context), [f"AXES[{axes}]"])


def _relies_on_default_axes(context: Context) -> bool:
    """Whether an axis keyword is written without its axes (no ``[...]`` list, no ``.n``) before
    the first AXES statement, in compile order: such a use acts on, or reads, the power-up default."""
    axis_keywords = context.mentioned(lambda name: axis_keyword(context, name))
    uses = context.keyword_uses(*axis_keywords)  # in compile order: the first bracket-less one decides
    bare = ((file, use.statement) for file, use in uses if use.keyword.selector is None and use.keyword.channel is None)
    first_bare = next(bare, None)
    if first_bare is None:
        return False
    axes = ((file, statement) for file, _, statement in context.statements(n.Axes) if isinstance(statement, n.Axes))
    first_axes = next(axes, None)
    return first_axes is None or _compile_place(*first_bare) < _compile_place(*first_axes)


def _compile_place(file: FileView, statement: n.Statement) -> tuple[int, int]:
    """Where a statement is in compile order: the configuration file before the program."""
    return (0 if file.unit is Unit.CONFIGURATION else 1, statement.span.start)


class InputEdges(Rule):
    """Each ``#INn`` handler's input is made negative-edge triggered, as v3 called #INn once
    per falling (active to inactive) edge; v4 inputs are level triggered by default and a
    level-triggered handler is called again and again while the input is active.

    Several handlers are flagged at the first: v3 served inputs that came together from #IN7
    down and let one input's handler interrupt another's (v3:2549); v4 serves #IN0 first and
    one handler at a time (v4:5062-5064), so handlers sharing variables or outputs may end
    otherwise.

    The inputs that would hold back a handler in v4 (``inputs_holding_back_handlers``) are masked off
    with IMASK.
    """

    id = "S-INEDGE"
    rule_class = RuleClass.SEMI
    phase = Phase.INSERTIONS
    summary = (
        "#INn handlers -> 'INPUTMODE = INPUTMODE | m' and 'INPUTNEGTRIGGER = INPUTNEGTRIGGER | m'; "
        "several handlers -> manual item (priority reversed)"
    )
    evidence = "spec S-INEDGE; v3:2525, v3:2549; v4:4085-4088, v4:5024-5040, v4:5062-5064, v4:12379-12421"

    def apply(self, context: Context) -> Iterator[Action]:
        mask = 0
        handlers: list[tuple[FileView, n.PlacedLine, n.Name]] = []
        for file, line in context.placed(LABEL):
            label = line.syntax.label
            event = event_of(label.text) if label is not None and file.unit is Unit.PROGRAM else None
            if event is not None and event.kind is EventKind.IN and event.number is not None:
                assert label is not None
                mask |= 1 << event.number
                handlers.append((file, line, label))
        if len(handlers) > 1:
            file, line, label = handlers[0]
            names = ", ".join(f"#{label.text}" for _, _, label in handlers)
            yield self.flag(
                file,
                line.span(label.span),
                f"{names}: v3 ran #IN7 first and let handlers interrupt each other, v4 runs #IN0 first and one "
                "at a time (v3:2549, v4:5062-5064): check what they share",
            )
        if not mask or _sets_input_mode(context):
            return
        lines = [f"INPUTMODE = INPUTMODE | {mask}", f"INPUTNEGTRIGGER = INPUTNEGTRIGGER | {mask}"]
        holding = inputs_holding_back_handlers(context)
        if holding:
            lines.append(f"IMASK = IMASK & 0x{imask_all_ones(context) & ~holding:X}")
        yield insert_lines(prologue_file(context), lines)


def _sets_input_mode(context: Context) -> bool:
    """Whether the application already writes INPUTMODE (a name to the v3 reader)."""
    for _, _, statement in context.statements(name_tag("INPUTMODE")):
        if isinstance(statement, n.Assignment) and statement.target.name.identity == "INPUTMODE":
            return True
    return False
