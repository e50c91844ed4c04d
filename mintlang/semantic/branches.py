"""Branches of an IF that a constant condition keeps from ever running.

Mint takes a zero condition for false and any other for true (v3:2009): ``IF 0 THEN``
never runs its statements, an ``IF 0 DO`` block never its part before ELSE, an
``IF 1 DO`` block never its part after ELSE (v3:2101, v3:2134). A tool asking
whether a program *does* something (writes a parameter) must not count such code.
"""

from __future__ import annotations

from collections.abc import Iterable

from mintlang.dialect import Dialect
from mintlang.semantic.blocks import Block, BlockKind, Place
from mintlang.semantic.constants import constant_value
from mintlang.syntax import nodes as n

Range = tuple[Place, Place | None]  # places strictly between the two never run (None: to the end of the file)


def dead_ranges(blocks: Iterable[Block], opener: dict[int, n.LineSyntax], dialect: Dialect) -> tuple[Range, ...]:
    """The parts of IF blocks whose condition is constant that never run; ``opener`` maps a
    line number to the syntax of the line opening a block there."""
    found: list[Range] = []
    for block in blocks:
        if block.kind is not BlockKind.IF:
            continue
        statement = n.flatten_statements(opener[block.opener.line].statements)[block.opener.index]
        if not isinstance(statement, n.IfDo):
            continue  # an IF line in error still opens its block, with no condition to read
        value = constant_value(statement.condition, dialect)
        if value == 0:
            found.append((block.opener, block.middle or block.closer))
        elif value is not None and block.middle is not None:
            found.append((block.middle, block.closer))
    return tuple(found)


def never_runs(
    statement: n.Statement, number: int, line: n.LineSyntax, ranges: tuple[Range, ...], dialect: Dialect
) -> bool:
    """Whether a constant condition keeps ``statement`` of ``line`` (starting on line ``number``) from running."""
    flat = n.flatten_statements(line.statements)
    index = next(position for position, each in enumerate(flat) if each is statement)
    place = Place(number, index)
    if any(start < place and (end is None or place < end) for start, end in ranges):
        return True
    return _in_false_then(statement, line.statements, dialect)


def _in_false_then(statement: n.Statement, statements: tuple[n.Statement, ...], dialect: Dialect) -> bool:
    for each in statements:
        if type(each) is n.IfThen:
            assert isinstance(each, n.IfThen)
            if any(inner is statement for inner in n.walk_statements(each.body)):
                return constant_value(each.condition, dialect) == 0 or _in_false_then(statement, each.body, dialect)
    return False
