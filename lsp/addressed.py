"""What a keyword written in the program addresses, and what the configuration file sets there.

``SPEED.xAxis`` acts on the axis the macro stands for, and the configuration
file, which runs first, may already have set ``SPEED`` for it: hover says both,
so nobody has to resolve the macro and search the other file by hand.
"""

from __future__ import annotations

from bisect import bisect_right
from collections.abc import Iterator

from mintlang.analysis.rules.addressing import addressed
from mintlang.diagnostics import Span
from mintlang.lsp.workspace import Snapshot
from mintlang.records import record
from mintlang.semantic.constants import constant_integer
from mintlang.semantic.index import KeywordUse, Use, line_facts
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n


@record
class Setting:
    """A value the configuration file writes to a keyword: for ``number`` (None: its default axes)."""

    number: int | None
    value: str
    line: int  # 1-based


def placed_line(snapshot: Snapshot, unit: Unit, offset: int) -> n.PlacedLine | None:
    """The logical line of ``unit``'s file that starts at or before ``offset``."""
    placed = snapshot.model.document(unit).placed
    index = bisect_right(placed, offset, key=lambda line: line.origin) - 1
    return placed[index] if index >= 0 else None


def keyword_use(snapshot: Snapshot, offset: int) -> tuple[n.PlacedLine, KeywordUse] | None:
    """The keyword use whose spelling is at ``offset`` of the snapshot's file."""
    line = placed_line(snapshot, snapshot.unit, offset)
    if line is None:
        return None
    for use in line_facts(snapshot.unit, line).keyword_uses:
        span = line.span(use.keyword.spelling_span)
        if span.start <= offset <= span.end:
            return line, use
    return None


def numbers(keyword: n.KeywordRef, snapshot: Snapshot) -> list[int | None] | None:
    """The axes or channel the keyword is written with, a macro's resolved (None for one known only at run
    time, such as a variable); None when it is written without any."""
    if keyword.channel is not None:
        return [keyword.channel]
    if keyword.selector is None:
        return None
    return [constant_integer(item, snapshot.document.dialect) for item in keyword.selector.items]


def described(snapshot: Snapshot, keyword: n.KeywordRef, noun: str) -> str:
    """ "axis 1", "axes 0, 2", "the default axes" or "an axis known when the line runs"."""
    found = numbers(keyword, snapshot)
    if found is None:
        return f"the default {'axes' if noun == 'axis' else noun}"
    if None in found:
        return f"{'an' if noun[0] in 'aeiou' else 'a'} {noun} known when the line runs"
    plural = ("axes" if noun == "axis" else f"{noun}s") if len(found) > 1 else noun
    return f"{plural} {', '.join(map(str, found))}"


def settings(snapshot: Snapshot, name: str) -> Iterator[Setting]:
    """The values the configuration file writes to the keyword ``name``, in its order."""
    model = snapshot.model
    if model.configuration is None:
        return
    index = model.configuration.line_index
    source = model.configuration.source
    for unit, line, facts in model.lines:
        if unit is not Unit.CONFIGURATION:
            continue
        for use in facts.keyword_uses:
            statement = use.statement
            if use.use is not Use.WRITE or use.keyword.keyword != name or type(statement) is not n.KeywordStatement:
                continue
            values = statement.values or ()  # type: ignore[union-attr]
            targets = numbers(use.keyword, snapshot)
            if targets is None:  # the default axes (AXES) take the values in turn (000:590-640): all of them
                written = line.span(Span(use.keyword.span.end, statement.span.end))
                value = source[written.start : written.end].strip().removeprefix("=").strip()
                yield Setting(None, value, index.position(written.start).line)
                continue
            for place, number in enumerate(targets):
                # An axis past the last value keeps its value unless a ";" fills the rest with it (000:578-580, 656-659)
                value = values[place] if place < len(values) else values[-1] if values and statement.fill else None  # type: ignore[union-attr]
                if value is not None:
                    span = line.span(value.span)
                    yield Setting(number, source[span.start : span.end], index.position(span.start).line)


def hover_lines(snapshot: Snapshot, offset: int) -> list[str]:
    """For an axis or channel keyword at ``offset``: what it addresses here, and, in the program, the
    values the configuration file sets for those axes or channels."""
    found = keyword_use(snapshot, offset)
    if found is None:
        return []
    _, use = found
    target = addressed(use.keyword.keyword, snapshot.model.controller)
    if target is None:
        return []
    noun = target[0]
    lines = [f"- Here: {described(snapshot, use.keyword, noun)}"]
    if snapshot.unit is Unit.PROGRAM:
        here = numbers(use.keyword, snapshot)
        for setting in settings(snapshot, use.keyword.keyword):
            if here is None or setting.number is None or setting.number in here:
                plural = "axes" if noun == "axis" else f"{noun}s"
                which = f"{noun} {setting.number}" if setting.number is not None else f"the default {plural}"
                lines.append(f"- The configuration file sets {which} to `{setting.value}` (line {setting.line})")
    return lines
