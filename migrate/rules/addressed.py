"""Which axes a motion statement acts on, and which axes an application moves.

A keyword with a bracket list or dot names its axes; a bracket-less one takes
the AXES default in force (``axes.default_axes``), one axis per value written
(``MOVEA = 10`` moves the first default axis only, ``SPEED = ,10`` the second, v3:1080-1109), all of them
for a command (``GO``) or a ``;`` fill. The circle moves take two axes and
three values. Several rules need these answers: the defaults and prologue
notes (which axes rely on v3 hardware and defaults) and the explicit-axes rewrite.
"""

from __future__ import annotations

import re
from collections.abc import Collection, Iterator

from mintlang.dialect import Dialect
from mintlang.keyworddb.model import CIRCLES
from mintlang.migrate.context import Context, FileView, name_tag, per_pass
from mintlang.migrate.rules.axes import default_axes, selector_axes
from mintlang.migrate.rules.base import keyword_refs, written
from mintlang.semantic.branches import Range, dead_ranges, never_runs
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n

POSITIONAL = frozenset({"MOVEA", "MOVER", "VECTORA", "VECTORR", *CIRCLES})  # profiled with SPEED
RAMPED = frozenset({*POSITIONAL, "JOG", "HOME", "OFFSET", "INCA", "INCR"})  # ramped with ACCEL and DECEL
MOVES = frozenset({*RAMPED, "FLY", "FOLLOW", "CAM", "CAMA", "PULSE", "GEARN"})


def addressed_axes(
    context: Context, file: FileView, statement: n.KeywordStatement, start: int
) -> tuple[int, ...] | None:
    """The axes ``statement``, starting at ``start`` of ``file``, acts on, or None when a list is
    computed or the default unknown (``start`` places a statement as parsed, see ``keyword_refs``)."""
    keyword = statement.keyword
    if keyword.selector is not None or keyword.channel is not None:
        return selector_axes(keyword)
    default = default_axes(context, file, start)
    if default is None:
        return None
    if keyword.keyword in CIRCLES:
        return default[:2] if len(default) >= 2 else None
    if statement.values is None or statement.fill:
        return default
    return default[: len(statement.values)] if len(statement.values) <= len(default) else None


@per_pass
def moved_axes(context: Context, keywords: Collection[str], running: bool = False) -> tuple[int, ...] | None:
    """The sorted axes the application writes any of ``keywords`` (a tuple or frozenset) on
    (``()`` when it never does), or None when one of those writes has axes that cannot be known.
    ``running``: leave out writes a constant IF condition keeps from running (``IF 0 THEN SPEED = 4``)."""
    found: set[int] = set()
    for file, line, statement, keyword in keyword_refs(context, *keywords):
        if not written(statement, keyword) or (running and _never_runs(context, file, line, statement)):
            continue
        assert isinstance(statement, n.KeywordStatement)  # written() holds only for keyword statements
        axes = addressed_axes(context, file, statement, line.origin + statement.span.start)
        if axes is None:
            return None
        found.update(axes)
    return tuple(sorted(found))


@per_pass
def writes_any(context: Context, names: Collection[str], running: bool = False) -> bool:
    """Whether the application writes one of ``names`` (a tuple or frozenset): a keyword the v3
    reader knows (``MFOLERR = 5``) or a v4-only keyword it reads as a variable (``HOMESPEED = 5``).
    ``running`` as for ``moved_axes``."""
    wanted = frozenset(names)
    for file, line, statement, keyword in keyword_refs(context, *wanted):
        if written(statement, keyword) and not (running and _never_runs(context, file, line, statement)):
            return True
    return writes_unplaced(context, wanted)


@per_pass
def writes_unplaced(context: Context, names: frozenset[str]) -> bool:
    """Whether the application writes one of ``names`` where the v3 reader cannot tell the axes:
    a v4-only keyword it reads as a variable (``HOMESPEED = 5``) or a statement it cannot parse
    (``FOLERRORFATAL = 2;``, the M-REN rename of a fill over every default axis)."""
    return any(word in names for word in _assigned(context, names))


def _assigned(context: Context, names: frozenset[str]) -> Iterator[str]:
    """The names assigned as variables and the words unparsable statements write (``FOLERRORFATAL
    = 2;``, a v4 fill the v3 reader cannot parse), on the lines that may write one of ``names``,
    each in upper case as written: the v3 reader knows a variable by its first ten characters, but
    ``DRIVEENABLE = 1`` is no write of ``DRIVEENABLEOUTPUT``. Read from the syntax as parsed: a
    statement's text starts at its line's origin plus its own start."""
    for file, line in context.placed(n.SyntaxError_, *map(name_tag, names)):
        for statement in n.flatten_statements(line.syntax.statements):
            if isinstance(statement, n.Assignment):
                yield statement.target.name.text.upper()
            elif type(statement) is n.SyntaxError_:
                word = unparsed_write(file.text[line.origin + statement.span.start : line.origin + statement.span.end])
                if word is not None:
                    yield word


def _never_runs(context: Context, file: FileView, line: n.PlacedLine, statement: n.Statement) -> bool:
    """Whether a constant IF condition keeps ``statement`` from ever running (v3:2009)."""
    return never_runs(statement, line.number, line.syntax, _dead_ranges(context, file.unit), Dialect.V3)


@per_pass
def _dead_ranges(context: Context, unit: Unit) -> tuple[Range, ...]:
    file = context.files[unit]
    lines = {placed.number: placed.syntax for placed in file.document.placed}
    return dead_ranges(context.model.structures[unit].blocks, lines, Dialect.V3)


_WRITE = re.compile(r"\s*([A-Za-z_]\w*)\s*(?:[.\[]|=)")


def unparsed_write(text: str) -> str | None:
    """The word a statement the v3 reader could not parse writes (``KPROP = 1.5;`` after M-REN), if any."""
    found = _WRITE.match(text)
    return found[1].upper() if found else None


V3_AXES = 3  # "MINT only supports the control of 3 axes on one controller" (v3:782)


def on_target(context: Context, axes: tuple[int, ...] | None) -> tuple[int, ...]:
    """``axes`` without those the target controller lacks, for the statements the migrator writes:
    one naming such an axis is error 2017 or 2 (v4:19047, v4:18514), and the lines using it are
    flagged where they are (X-CHECK). The axes of a v3 controller the target has when ``axes`` is
    None (not known) or names none it has: a v3 program addressed no other, and the moves flagged
    will have to run on one of those. ``()`` stays ``()``."""
    every = tuple(range(min(V3_AXES, context.controller.axis_count)))
    if axes is None:
        return every
    return tuple(axis for axis in axes if axis in context.controller.axes) or (every if axes else ())


def axis_list(axes: tuple[int, ...]) -> str:
    return f"[{','.join(str(axis) for axis in axes)}]"


@per_pass
def read_axes(context: Context, keywords: Collection[str]) -> tuple[int, ...] | None:
    """The sorted axes the application reads any of ``keywords`` (a tuple or frozenset) on; a
    bracket-less read is the first default axis (v3:1127). None when one of them cannot be known.

    A v4 keyword the v3 reader does not know is a user name when bare: ``IF HOMESWITCH THEN``, as
    S-READ writes ``IF HOME THEN``, reads a name, and that read is the first default axis too."""
    found: set[int] = set()
    for file, line, statement, keyword in keyword_refs(context, *keywords):
        if written(statement, keyword):
            continue
        if keyword.selector is not None or keyword.channel is not None:
            axes = selector_axes(keyword)
        else:
            default = default_axes(context, file, line.origin + statement.span.start)
            axes = default[:1] if default else None
        if axes is None:
            return None
        found.update(axes)
    for file, start in _bare_name_reads(context, keywords):
        default = default_axes(context, file, start)
        if not default:
            return None
        found.add(default[0])
    return tuple(sorted(found))


def _bare_name_reads(context: Context, names: Collection[str]) -> Iterator[tuple[FileView, int]]:
    """Where a statement reads one of ``names`` as a user name: the file and where the statement starts."""
    wanted = frozenset(map(n.identity, names))
    for file, line in context.placed(*map(name_tag, names)):
        for statement in n.flatten_statements(line.syntax.statements):
            for root in n.expressions_of(statement):
                for node in n.walk_expression(root):
                    if isinstance(node, n.VariableRef) and node.name.identity in wanted:
                        yield file, line.origin + statement.span.start
