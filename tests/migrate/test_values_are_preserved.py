"""Rules that change values keep what the v3 program computed: a tiny evaluator reads the
v3 expression with v3 semantics and the migrated one with v4 semantics, and both agree.

v3 semantics (v3 guide): SIN/COS/TAN return the value times 1000 (v3:2063-2067); ``~``
toggles 8 bits (v3:1978); SCALE truncates to an integer (v3:4759); AND binds tighter
than OR (v3:1994). v4 (v4 guide): trig returns the fraction (v4:8679); ``~`` is 24-bit
(v4:5708); ``|`` binds tighter than ``&`` (v4:1427); ``&``/``|`` are bitwise (v4:1310).
"""

from __future__ import annotations

import math

import pytest

import mintlang
from mintlang.migrate import migrate
from mintlang.migrate.rules.reads import ERROR_BITS, MODE_BITS
from mintlang.syntax import nodes as n


def _evaluate(expression: n.Expression, dialect: str, names: dict[str, float]) -> float:
    def value(node: n.Expression) -> float:
        match node:
            case n.Number(value=number):
                return number
            case n.VariableRef(name=name) | n.ConstantRef(name=name):
                return names[str(name.text if isinstance(name, n.Name) else name).upper()]
            case n.Parenthesised(expression=inner):
                return value(inner)
            case n.Call(function=function, arguments=(argument,)):
                result = {"SIN": math.sin, "COS": math.cos, "TAN": math.tan}[function](math.radians(value(argument)))
                return result * 1000 if dialect == "v3" else result
            case n.Unary(operator="~", operand=operand):
                return float(~int(value(operand)) & (0xFF if dialect == "v3" else 0xFFFFFF))
            case n.Binary(operator=operator, left=left, right=right):
                a, b = value(left), value(right)
                return {
                    "+": lambda: a + b,
                    "*": lambda: a * b,
                    "/": lambda: a / b,
                    "=": lambda: float(a == b),
                    "<>": lambda: float(a != b),
                    "AND": lambda: float(int(a) & int(b)),
                    "OR": lambda: float(int(a) | int(b)),
                }[operator]()
        raise AssertionError(f"cannot evaluate {node}")

    return value(expression)


def _v3_and_v4(source: str, names: dict[str, float]) -> tuple[float, float]:
    migrated = migrate(source, only=["M-TRIG", "M-TILDE", "M-PREC"]).text
    v3 = mintlang.parse(source, "v3").lines[0].statements[0]
    v4 = mintlang.parse(migrated, "v4").lines[0].statements[0]
    assert isinstance(v3, n.Assignment) and isinstance(v4, n.Assignment)
    return _evaluate(v3.value, "v3", names), _evaluate(v4.value, "v4", names)


@pytest.mark.parametrize("angle", [0, 30, 45, 60, 90, 135, 200, 330])
def test_trigonometry_gives_v3_thousandths(angle: int) -> None:
    for function in ("SIN", "COS"):
        v3, v4 = _v3_and_v4(f"x = {function}(a) + 1\n", {"A": angle})
        assert v4 == pytest.approx(v3, abs=1e-9)
    v3, v4 = _v3_and_v4("x = SIN a * 2\n", {"A": angle})  # v3 binds SIN a, then * 2
    assert v4 == pytest.approx(v3, abs=1e-9)


def test_v3_trig_reference_values() -> None:
    v3, v4 = _v3_and_v4("x = COS(30)\n", {})
    assert round(v3) == 866 and round(v4) == 866  # v3:2063 COS(30) = 866


@pytest.mark.parametrize("byte", [0, 1, 5, 127, 128, 255])
def test_tilde_gives_the_v3_byte(byte: int) -> None:
    v3, v4 = _v3_and_v4("x = ~b\n", {"B": byte})
    assert v3 == v4 == 255 - byte


@pytest.mark.parametrize("bits", range(8))
def test_mixed_and_or_reads_as_v3_did(bits: int) -> None:
    """The shared parser reads AND/OR with v4 precedence, so the v3 value is computed here
    from the v3 rule (AND first); the migrated text, read as v4, gives that value."""
    a, b, c = bits & 1, bits >> 1 & 1, bits >> 2 & 1
    migrated = migrate("x = a AND b OR c\n", only=["M-PREC"]).text
    statement = mintlang.parse(migrated, "v4").lines[0].statements[0]
    assert isinstance(statement, n.Assignment)
    assert _evaluate(statement.value, "v4", {"A": a, "B": b, "C": c}) == float((a & b) | c)


@pytest.mark.parametrize("value", [400, 2.5, 0.75, 1999.99])
def test_scale_is_truncated_like_v3(value: float) -> None:
    migrated = migrate(f"SCALE = {value}\n", only=["M-SCALE"]).text
    written = mintlang.parse(migrated, "v4").lines[0].statements[0]
    assert isinstance(written, n.KeywordStatement) and written.values
    argument = written.values[0]
    result = int(argument.arguments[0].value) if isinstance(argument, n.Call) else argument.value  # type: ignore[union-attr]
    assert result == int(value)  # v3 accepts integers only and rounds fractions down


@pytest.mark.parametrize("ramp", [0, 1, 5, 10])
def test_ramp_range_maps_onto_sramp(ramp: int) -> None:
    migrated = migrate(f"RAMP = {ramp}\n", only=["S-RAMP"]).text
    assert migrated == f"SRAMP = {ramp * 10}\n"  # v3 0..10 (v3:11212) -> v4 0..100 (v4:2838)


def test_mode_and_error_bits_name_the_same_state() -> None:
    """Every v3 enumeration value maps to a v4 bit that the v4 constant table defines as one bit."""
    constants = mintlang.keyworddb.database().constants
    for name in MODE_BITS.values():
        value = int(constants[name.upper()].value)
        assert value and value & (value - 1) == 0, name
    limit = ERROR_BITS[3].strip("()").split(" | ")
    assert {int(constants[bit.upper()].value) for bit in limit} == {2, 4}


def test_analogue_formula_in_the_manual_item_maps_the_v3_range() -> None:
    """(ADC + 100) * 1023 / 200 maps v4's -100..100 % onto v3's 0..1023 counts (+-10 V)."""
    formula = lambda adc: (adc + 100) * 1023 / 200  # noqa: E731
    assert (formula(-100), formula(0), formula(100)) == (0, 511.5, 1023)
