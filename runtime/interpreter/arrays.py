"""Arrays as their DIM makes them: sized and filled from constants when the program is compiled (NM-7).

``DIM a(3) = 1,2;`` fills the rest with the last value, and unwritten elements
are 0. A DIM that cannot make its array (a size that is not a whole number from
1, values that are not constants, more values than elements) raises that when its line runs instead.
"""

from __future__ import annotations

from collections.abc import Callable

from mintlang.runtime.errors import INVALID_INDEX, SYNTAX_ERROR, MintError
from mintlang.runtime.numbers import held
from mintlang.syntax import nodes as n


def array_problem(statement: n.Dim, number: Callable[[float], float]) -> MintError | None:
    """Why the array of ``statement`` (a DIM with a size) cannot be made, its elements held as ``number`` holds
    a value (the dialect's); None when it can."""
    size = constant(statement.size)
    if size is None or size < 1 or size != int(size):
        return MintError(INVALID_INDEX, detail=f"the size of array {statement.name.text} must be a whole number from 1")
    if any(constant(value) is None for value in statement.values):
        detail = f"array {statement.name.text} is initialised with values that are not constants"
        return MintError(SYNTAX_ERROR, detail=detail)
    if len(statement.values) > size:
        detail = f"array {statement.name.text} has {int(size)} elements: {len(statement.values)} values are too many"
        return MintError(INVALID_INDEX, detail=detail)
    for value in statement.values:
        try:
            held(constant(value), number)  # type: ignore[arg-type]
        except MintError as problem:
            return problem
    return None


def initial_values(statement: n.Dim) -> list[float]:
    """The elements of an array ``array_problem`` accepts, as its DIM initialises them."""
    size = int(constant(statement.size) or 0)
    initial = [value for value in map(constant, statement.values) if value is not None]
    if statement.fill and initial:
        initial += [initial[-1]] * (size - len(initial))
    return initial + [0.0] * (size - len(initial))


def constant(expression: n.Expression | None) -> float | None:
    """The value of a literal, possibly negated; arrays are initialised from constants only."""
    if type(expression) is n.Number or type(expression) is n.CharConstant:
        return float(expression.value)  # type: ignore[union-attr]
    if type(expression) is n.Unary and expression.operator in ("-", "+"):
        inner = constant(expression.operand)
        return None if inner is None else (-inner if expression.operator == "-" else inner)
    if type(expression) is n.Parenthesised:
        return constant(expression.expression)
    return None
