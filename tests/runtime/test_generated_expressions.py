"""An expression compiled into one generated Python function means what its operators mean, applied in order.

The runtime writes arithmetic out as Python text with the binary32 rounding
inline (``runtime/interpreter/generated.py``); the reference here walks the
same tree and calls the dialect's operator functions one by one, left operand
first, as the manual's numeric model defines them (``numbers.py``, NM-1, NM-3).
"""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from mintlang.controllers import NestingLimits
from mintlang.diagnostics import Span
from mintlang.runtime.clock import Clock
from mintlang.runtime.dialects.v3.semantics import V3
from mintlang.runtime.dialects.v4 import V4
from mintlang.runtime.errors import MintError, NotSimulated
from mintlang.runtime.interpreter.expressions import ExpressionCompiler, Names
from mintlang.runtime.interpreter.vm import Interpreter
from mintlang.runtime.semantics import Semantics
from mintlang.syntax import nodes as n

from .running import simulate

AT = Span(0, 0)
VARIABLES = ("a", "b", "c")
BINARY = ("+", "-", "*", "/", "=", "<>", "<", ">", "<=", ">=", "MOD", "AND", "OR", "XOR")
UNARY = ("-", "+", "NOT", "~")
LIMITS = NestingLimits(if_blocks=255, for_loops=50, gosub=100, other_loops=50, loops_and_ifs=255)

SMALL = [0.0, 1.0, 2.0, -1.0, 0.5, 3.0, 0.1, -2.5, 1000.0, 8388607.0]  # v3 holds up to 2**23 in 24.8 fixed point
LARGE = [16777215.0, 16777216.0, 1e19, 3e38]  # binary32 only: past 2**24 and near its largest value


def _expressions(semantics: Semantics, values: list[float]) -> st.SearchStrategy[n.Expression]:
    binary = st.sampled_from([operator for operator in BINARY if operator in semantics.binary])
    unary = st.sampled_from([operator for operator in UNARY if operator in semantics.unary])

    def grown(children: st.SearchStrategy[n.Expression]) -> st.SearchStrategy[n.Expression]:
        return st.one_of(
            st.builds(lambda op, left, right: n.Binary(AT, op, left, right), binary, children, children),
            st.builds(lambda op, operand: n.Unary(AT, op, operand), unary, children),
            children.map(lambda inner: n.Parenthesised(AT, inner)),
        )

    leaves = st.one_of(
        st.sampled_from(values).map(lambda value: n.Number(AT, repr(value), value)),
        st.sampled_from(VARIABLES).map(lambda name: n.VariableRef(AT, n.Name(name, AT))),
    )
    return st.recursive(leaves, grown, max_leaves=8)


def _reference(expression: n.Expression, semantics: Semantics, values: dict[str, float]) -> float:
    kind = type(expression)
    if kind is n.Number:
        return semantics.number(expression.value)  # type: ignore[union-attr]
    if kind is n.VariableRef:
        return values[expression.name.identity]  # type: ignore[union-attr]
    if kind is n.Parenthesised:
        return _reference(expression.expression, semantics, values)  # type: ignore[union-attr]
    if kind is n.Unary:
        operand = _reference(expression.operand, semantics, values)  # type: ignore[union-attr]
        return semantics.unary[expression.operator](operand)  # type: ignore[union-attr]
    left = _reference(expression.left, semantics, values)  # type: ignore[union-attr]
    right = _reference(expression.right, semantics, values)  # type: ignore[union-attr]
    return semantics.binary[expression.operator](left, right)  # type: ignore[union-attr]


def _outcome(evaluate) -> float | str:
    """The value, or the Mint error (its number) or the limit of the simulation raised instead."""
    try:
        return evaluate()
    except MintError as error:
        return f"error {error.code}"
    except NotSimulated as missing:
        return str(missing)


def _compiled(expression: n.Expression, semantics: Semantics, values: dict[str, float]):
    vm = Interpreter(Clock(), LIMITS)
    names = Names()
    for name, value in values.items():
        names.scalars[name] = len(vm.scalars)
        vm.scalars.append(value)
    return ExpressionCompiler(vm, None, names, semantics).compile(expression)  # type: ignore[arg-type]


@pytest.mark.parametrize(("semantics", "numbers"), [(V4, SMALL + LARGE), (V3, SMALL)], ids=["v4", "v3"])
@given(data=st.data())
def test_a_compiled_expression_applies_the_dialects_operators_in_order(
    semantics: Semantics, numbers: list[float], data: st.DataObject
) -> None:
    expression = data.draw(_expressions(semantics, numbers))
    values = {name.upper(): semantics.number(data.draw(st.sampled_from(numbers))) for name in VARIABLES}
    compiled = _compiled(expression, semantics, values)
    assert repr(_outcome(compiled)) == repr(_outcome(lambda: _reference(expression, semantics, values)))


def test_each_operation_rounds_to_binary32_and_a_sum_past_2_to_the_24_loses_the_one() -> None:
    # 16777216 + 1 = 16777217 needs 25 bits: binary32 rounds it to the even neighbour 16777216 (NM-1)
    result = simulate("DIM a = 16777216\nDIM b\nb = a + 1 - a\nPRINT b\n")
    assert result.terminal == "0\n"


def test_a_product_too_large_for_binary32_is_error_3_where_it_is_computed() -> None:
    # 1e8 ** 4 = 1e32 is binary32's; 1e40 is beyond its largest, 3.4e38 (NM-1)
    result = simulate("DIM a = 100000000\nDIM b\nb = a * a * a * a * a > 0\nPRINT b\n")
    assert (result.err, result.erl) == (3.0, 3.0)
