"""Which axes a bracket-less keyword addresses: the AXES default in force at a statement.

v3 powers up with ``AXES[0,1,2]`` (v3:1029-1033). Configuration files set AXES
once, in straight-line code, so the default at a statement is taken from the
last ``AXES[...]`` with constant axes written before it, in compile order
(configuration, then program). An AXES inside a block or with a computed list
makes the default unknown, and the rules that need it fall back to a manual item.
"""

from __future__ import annotations

from bisect import bisect_left
from dataclasses import dataclass

from mintlang.migrate.context import Context, FileView
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n

V3_POWER_UP_AXES = (0, 1, 2)


def default_axes(context: Context, file: FileView, offset: int) -> tuple[int, ...] | None:
    """The axes bracket-less keywords address at ``offset`` of ``file``, or None when unknown:
    the default in force before the first statement of ``file`` starting at or after ``offset``."""
    timeline = context.memo(_Timeline.build)
    starts, positions = timeline.files.get(file.unit, ((), ()))
    found = bisect_left(starts, offset)
    return timeline.before[positions[found] if found < len(positions) else -1]


@dataclass(frozen=True, slots=True)
class _Timeline:
    """The AXES default before each statement in compile order (one more at the end, after the
    last), and for each file the running maximum of its statements' starts with their positions,
    so a lookup is a bisection (the maximum keeps it right if a body were listed out of order)."""

    before: tuple[tuple[int, ...] | None, ...]
    files: dict[Unit, tuple[list[int], list[int]]]

    @classmethod
    def build(cls, context: Context) -> _Timeline:
        """Read from the syntax as parsed (a statement starts at its line's origin plus its own
        start): every statement takes part, and none needs copying with file offsets."""
        axes: tuple[int, ...] | None = V3_POWER_UP_AXES
        before = []
        files: dict[Unit, tuple[list[int], list[int]]] = {}
        position = 0
        for file, line in context.placed():
            starts, positions = files.setdefault(file.unit, ([], []))
            for statement in n.flatten_statements(line.syntax.statements):
                before.append(axes)
                starts.append(max(line.origin + statement.span.start, starts[-1] if starts else 0))
                positions.append(position)
                position += 1
                if type(statement) is n.Axes:
                    axes = constant_axes(statement.selector) if _top_level(line.syntax, statement) else None
        before.append(axes)
        return cls(tuple(before), files)


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
