"""Which axes a bracket-less keyword addresses: the AXES default in force at a statement.

v3 powers up with ``AXES[0,1,2]`` (v3:1029-1033). Configuration files set AXES
once, in straight-line code, so the default at a statement is taken from the
last ``AXES[...]`` with constant axes written before it, in compile order
(configuration, then program). An AXES inside a block or with a computed list
makes the default unknown, and the rules that need it fall back to a manual item.
So does an AXES in a subroutine (below a label) for the lines above it in its file
and for the files after it: a GOSUB runs it before them (``GOSUB init`` first,
v3:873-901); below it, as the guide's ``#init`` then ``#main``, its default holds.
"""

from __future__ import annotations

from bisect import bisect_left

from mintlang.migrate.context import LABEL, Context, FileView
from mintlang.records import record
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n

V3_POWER_UP_AXES = (0, 1, 2)


Axes = tuple[int, ...] | None


def default_axes(context: Context, file: FileView, offset: int) -> Axes:
    """The axes bracket-less keywords address at ``offset`` of ``file``, or None when unknown:
    the default in force before the first statement of ``file`` starting at or after ``offset``
    (after the last statement of the application when there is none)."""
    timeline = context.memo(_Timeline.build)
    last = timeline.last.get(file.unit)
    if last is None or last < offset:
        return timeline.final
    starts, defaults = timeline.changes.get(file.unit, ((), ()))
    found = bisect_left(starts, offset)  # the AXES statements before that statement
    return defaults[found - 1] if found else timeline.entering[file.unit]


@record
class _Timeline:
    """Per file: where each AXES statement starts and the default after it, the default in force
    as the file starts, and where its last statement starts; the default after the whole
    application. A lookup is a bisection. A statement starts at or after every statement of the
    lines above it, so only the lines with an AXES statement, and each file's last, are read."""

    changes: dict[Unit, tuple[list[int], list[Axes]]]
    entering: dict[Unit, Axes]
    last: dict[Unit, int]
    final: Axes

    @classmethod
    def build(cls, context: Context) -> _Timeline:
        changes: dict[Unit, tuple[list[int], list[Axes]]] = {}
        first_label: dict[Unit, int] = {}  # where each file's first label line starts
        for file, line in context.placed(LABEL):
            first_label.setdefault(file.unit, line.origin)
        in_subroutine: set[Unit] = set()  # the files with an AXES below a label
        for file, line in context.placed(n.Axes):
            if file.unit in first_label and line.origin > first_label[file.unit]:
                in_subroutine.add(file.unit)
            starts, defaults = changes.setdefault(file.unit, ([], []))
            latest = -1  # the greatest start so far on the line: a body is read after its IF
            for statement in n.flatten_statements(line.syntax.statements):
                latest = max(latest, line.origin + statement.span.start)
                if type(statement) is n.Axes:
                    starts.append(latest)
                    defaults.append(constant_axes(statement.selector) if _top_level(line.syntax, statement) else None)
        axes: Axes = V3_POWER_UP_AXES
        entering: dict[Unit, Axes] = {}
        last: dict[Unit, int] = {}
        for file in context.compiled:
            entering[file.unit] = None if file.unit in in_subroutine else axes
            axes = changes[file.unit][1][-1] if file.unit in changes else axes
            if file.unit in in_subroutine:
                axes = None  # whether and when the subroutine ran is not known
            final = _last_start(file.document.placed)
            if final is not None:
                last[file.unit] = final
        return cls(changes, entering, last, axes)


def _last_start(lines: tuple[n.PlacedLine, ...]) -> int | None:
    """Where the last statement of a file starts (the greatest start on its last line with any)."""
    for line in reversed(lines):
        if line.syntax.statements:
            return max(line.origin + statement.span.start for statement in n.flatten_statements(line.syntax.statements))
    return None


def constant_axes(selector: n.Selector | None) -> tuple[int, ...] | None:
    if selector is None:
        return None
    found = []
    for item in selector.items:
        if not isinstance(item, n.Number) or item.value != int(item.value):
            return None
        found.append(int(item.value))
    return tuple(found)


def selector_axes(keyword: n.KeywordRef) -> tuple[int, ...] | None:
    """The constant axes a keyword names itself (``[0,1]``, ``.1``, ``IN3``), else None."""
    if keyword.channel is not None:
        return (keyword.channel,)
    return constant_axes(keyword.selector)


def _top_level(line: n.LineSyntax, statement: n.Statement) -> bool:
    """Whether ``statement``, one of ``line``'s, stands on the line itself, not in an IF .. THEN
    body: by identity (``in`` would compare statements by value, and a body may repeat one)."""
    return any(top is statement for top in line.statements)


def axis_values(
    context: Context, file: FileView, statement: n.KeywordStatement
) -> tuple[tuple[int, n.Expression], ...]:
    """The (axis, value) pairs a keyword write assigns, or () when its axes are not constant.

    Values go to the named axes (or the AXES default) in order, a ``;`` fill repeats
    the last value, and a skipped place leaves its axis alone.
    """
    keyword = statement.keyword
    axes = selector_axes(keyword)
    if axes is None and keyword.selector is None:
        axes = default_axes(context, file, statement.span.start)
    if axes is None or not statement.values:
        return ()
    values = list(statement.values)
    if statement.fill:
        values += [values[-1]] * (len(axes) - len(values))
    return tuple((axis, value) for axis, value in zip(axes, values, strict=False) if value is not None)


def selector_for(axes: tuple[int, ...]) -> str:
    """The explicit selector of ``axes``: ``.n`` for one axis, ``[a,b]`` for several."""
    return f".{axes[0]}" if len(axes) == 1 else f"[{','.join(str(axis) for axis in axes)}]"
