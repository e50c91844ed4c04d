"""Value changes of S-ANALOG and S-GEAR keep what the v3 program computed.

v3 (v3:5748-5760, v3:4368-4376): ANALOGUEn reads one part in 1024 of +-10 V, 512 at 0 V. v4 (v4:6358-6363): ADC reads
-100..100 % of +-10 V. v3 gear ratio = GEARN/GEARD (v3:3762); v4 ratio = FOLLOW/FOLLOWDENOM
(v4:3495), FOLLOW alone where FOLLOWDENOM is absent.
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest

import mintlang
from mintlang.migrate import migrate
from mintlang.syntax import nodes as n


def _value(node: n.Expression, inputs: dict[str, float]) -> float:
    match node:
        case n.Number(value=number):
            return number
        case n.KeywordRef(keyword=keyword, selector=selector):
            channel = f".{selector.items[0].value:g}" if selector is not None else ""  # type: ignore[union-attr]
            return inputs[keyword + channel]
        case n.Parenthesised(expression=inner):
            return _value(inner, inputs)
        case n.Unary(operator="-", operand=operand):
            return -_value(operand, inputs)
        case n.Call(function="INT", arguments=(argument,)):  # the whole part (v4:12565)
            return float(math.trunc(_value(argument, inputs)))
        case n.Binary(operator=operator, left=left, right=right):
            a, b = _value(left, inputs), _value(right, inputs)
            relation = float(a >= b)  # 1 when true, 0 when false (v4:1266)
            return {"+": a + b, "-": a - b, "*": a * b, "/": a / b if b else 0.0, ">=": relation}[operator]
    raise AssertionError(f"cannot evaluate {node}")


def _assigned(text: str, dialect: str) -> n.Expression:
    statement = next(s for line in mintlang.parse(text, dialect).lines for s in line.statements)
    assert isinstance(statement, n.Assignment)
    return statement.value


@pytest.mark.parametrize("volts", [-10.0, -7.5, -1.0, 0.0, 2.5, 9.99, 10.0])
def test_analogue_counts_are_kept_for_a_ten_volt_input(volts: float) -> None:
    source = "x = A2 - 512\n"
    migrated = migrate(source, only=["S-ANALOG"]).text.splitlines()[-1] + "\n"
    # v3: whole 1024ths of -10..+10 V, 512 at 0 V (v3:4368-4376, 5760), 10 bits reading 0 to 1023 (v3:5748-5750)
    counts = min(math.floor((volts + 10) / 20 * 1024), 1023)
    v3 = _value(_assigned(source, "v3"), {"ANALOGUE2": counts})
    v4 = _value(_assigned(migrated, "v4"), {"ADC.1": volts * 10})
    assert v4 == pytest.approx(v3, abs=1e-9)


@pytest.mark.parametrize(("numerator", "denominator"), [(2, 10), (8, 10), (-3, 4), (127, 128), (5, 1000), (1, 3)])
@pytest.mark.parametrize("controller", ["nextmove-pci", "mintdrive"])
def test_gear_ratio_is_kept(numerator: int, denominator: int, controller: str) -> None:
    migrated = migrate(f"GEARD = {denominator}\nGEARN = {numerator}\n", only=["S-GEAR"], controller=controller).text
    statements = [s for line in mintlang.parse(migrated, "v4").lines for s in line.statements]
    written = {s.keyword.keyword: s.values[0] for s in statements if isinstance(s, n.KeywordStatement) and s.values}
    follow = _value(written["FOLLOW"], {})  # type: ignore[arg-type]
    denom = _value(written["FOLLOWDENOM"], {}) if "FOLLOWDENOM" in written else 1.0  # type: ignore[arg-type]
    assert Fraction(follow) / Fraction(denom) == pytest.approx(Fraction(numerator, denominator), abs=1e-12)
