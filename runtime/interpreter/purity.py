"""Statements that act on the interpreter alone.

A statement is *pure* when running it reads nothing that changes with time or
the world and changes nothing but the interpreter's own state: variables,
arrays, the program counter and the loop and GOSUB stacks. Arithmetic on
variables, jumps and the loop words are pure; anything naming a keyword,
``PRINT``, ``INPUT``, ``PAUSE``, ``WAIT``, ``END`` and ``RETURN`` (which ends an
event handler too) are not. On ticks where nothing else can change, the
simulator runs pure statements without the rest of the tick's work
(``Simulator.run``), 20 a tick as ever.

A pure statement that fails can be run again in a tick processed whole, to
fail there with the whole machine up to date: it has changed nothing when it
raises, or, for ``FOR`` (which sets its variable before it pushes its loop,
and that may overflow the stack), it sets the variable to the same value again
unless its start, limit or step reads the variable itself, which makes it not pure.
"""

from __future__ import annotations

from collections.abc import Mapping

from mintlang.semantic.blocks import Block, BlockKind, Place
from mintlang.syntax import nodes as n

_PURE_WORDS = frozenset({"NEXT", "ENDW", "ENDL", "ELSE", "ENDIF", "REPEAT", "LOOP", "EXIT"})
_PURE_VALUES = frozenset(
    {n.Number, n.CharConstant, n.ConstantRef, n.VariableRef, n.ElementRef, n.Parenthesised, n.Unary, n.Binary}
)


def is_pure(statement: n.Statement, functions: Mapping[str, object]) -> bool:
    """Whether ``statement`` is pure, the dialect's numeric ``functions`` (SIN, ABS …) being pure."""
    kind = type(statement)
    if kind is n.Assignment:
        return _reads_nothing(statement.target, functions) and _reads_nothing(statement.value, functions)  # type: ignore[union-attr]
    if kind is n.IfThen or kind is n.IfDo or kind is n.While or kind is n.Until:
        return _reads_nothing(statement.condition, functions)  # type: ignore[union-attr]
    if kind is n.Dim:
        return all(_reads_nothing(value, functions) for value in statement.values)  # type: ignore[union-attr]
    if kind is n.BlockWord:
        return statement.word in _PURE_WORDS  # type: ignore[union-attr]
    if kind is n.For:
        return _for_repeats(statement, functions)  # type: ignore[arg-type]
    return kind is n.Jump or kind is n.Define


def endw_as_its_while(pure: bytearray, blocks: tuple[Block, ...], positions: Mapping[Place, int]) -> None:
    """An ``ENDW`` tests its ``WHILE``'s condition again: it is pure only when that ``WHILE`` is (``TIME`` read
    there changes from tick to tick)."""
    for block in blocks:
        if block.kind is BlockKind.WHILE and block.closer is not None:
            closer = positions[block.closer]
            pure[closer] = pure[closer] and pure[positions[block.opener]]


def _for_repeats(statement: n.For, functions: Mapping[str, object]) -> bool:
    """Whether the FOR reads nothing outside the interpreter, nor its own variable (run again, it does the same)."""
    variable = statement.variable.identity
    bounds = (statement.start, statement.end, *((statement.step,) if statement.step is not None else ()))
    return all(
        _reads_nothing(bound, functions)
        and not any(type(part) is n.VariableRef and part.name.identity == variable for part in n.walk_expression(bound))  # type: ignore[union-attr]
        for bound in bounds
    )


def _reads_nothing(expression: n.Expression, functions: Mapping[str, object]) -> bool:
    """Whether ``expression`` reads only variables, arrays and literals, through operators and numeric functions."""
    return all(
        type(part) in _PURE_VALUES or (type(part) is n.Call and part.function in functions)  # type: ignore[union-attr]
        for part in n.walk_expression(expression)
    )
