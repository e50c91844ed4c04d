"""Rules that change values keep what the v3 program computed: a tiny evaluator reads the
v3 expression with v3 semantics and the migrated one with v4 semantics, and both agree.

v3 semantics (v3 guide): SIN/COS/TAN return the value times 1000 (v3:2063-2067); ``~``
toggles 8 bits (v3:1978); SCALE truncates to an integer (v3:4759); AND binds tighter
than OR (v3:1994). v4 (v4 guide): trig returns the fraction (v4:8679); ``~`` is 24-bit
(v4:5708); ``|`` binds tighter than ``&`` (v4:1427); ``&``/``|`` are bitwise (v4:1310).
"""

from __future__ import annotations

import math
from collections.abc import Mapping

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
            case n.KeywordRef(keyword=keyword, selector=selector) if selector is not None:
                return names[f"{keyword}.{selector.items[0].value:g}"]  # type: ignore[union-attr]
            case n.Unary(operator="-", operand=operand):
                return -value(operand)
            case n.Unary(operator="NOT", operand=operand):  # logical in both (v3:10308, v4:1352)
                return float(not value(operand))
            case n.Parenthesised(expression=inner):
                return value(inner)
            case n.Call(function="INT", arguments=(argument,)):  # the whole part (v4:12565)
                return float(math.trunc(value(argument)))
            case n.Call(function=function, arguments=(argument,)):
                result = {"SIN": math.sin, "COS": math.cos, "TAN": math.tan}[function](math.radians(value(argument)))
                return result * 1000 if dialect == "v3" else result
            case n.Unary(operator="~", operand=operand):
                return float(~int(value(operand)) & (0xFF if dialect == "v3" else 0xFFFFFF))
            case n.Binary(operator=operator, left=left, right=right):
                a, b = value(left), value(right)
                return {
                    "+": lambda: a + b,
                    "-": lambda: a - b,
                    "*": lambda: a * b,
                    "/": lambda: a / b,
                    "=": lambda: float(a == b),
                    "<>": lambda: float(a != b),
                    ">=": lambda: float(a >= b),
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
    assert migrated.splitlines()[-1] == f"SRAMP = {ramp * 10}"  # v3 0..10 (v3:11212) -> v4 0..100 (v4:2838)


def test_mode_and_error_bits_name_the_same_state() -> None:
    """Every v3 enumeration value maps to a v4 bit that the v4 constant table defines as one bit."""
    constants = mintlang.keyworddb.database().constants
    for name in MODE_BITS.values():
        value = int(constants[name.upper()].value)
        assert value and value & (value - 1) == 0, name
    limit = ERROR_BITS[3].strip("()").split(" | ")
    assert {int(constants[bit.upper()].value) for bit in limit} == {2, 4}


def test_analogue_formula_maps_the_v3_range() -> None:
    """INT((ADC + 100) * 1024 / 200) - (ADC >= 100) maps v4's -100..100 % onto v3's counts (+-10 V): one
    part in 1024 (v3:4368), 0 V reads 512 ("0V input produces zero speed" from A1 - 512, v3:4376), and
    the 10 bits read 0 to 1023 (v3:5748-5750), so ANALOGUE1-512 spans -512 to 511 (v3:5768 says 512)."""
    migrated = migrate("x = A1 - 512\n", only=["S-ANALOG"]).text.splitlines()[-1]
    statement = mintlang.parse(migrated + "\n", "v4").lines[0].statements[0]
    assert isinstance(statement, n.Assignment)
    spans = [_evaluate(statement.value, "v4", {"ADC.0": percent}) for percent in (-100, 0, 100)]
    assert spans == [-512, 0, 511]


@pytest.mark.parametrize("mask", ["0", "15", "000001111", "0101", "255"])
def test_input_mask_keeps_the_v3_bits_and_enables_the_rest(mask: str) -> None:
    """v3 IMASK bits 0..7 are kept; bits 8..19 (NextMove PCI, v4:11896) stay at v4's default 1."""
    migrated = migrate(f"IMASK = {mask}\n", only=["S-IMASK"]).text
    v3 = mintlang.parse(f"IMASK = {mask}\n", "v3").lines[0].statements[0]
    v4 = mintlang.parse(migrated, "v4").lines[0].statements[0]
    assert isinstance(v3, n.KeywordStatement) and v3.values and v3.values[0] is not None
    assert isinstance(v4, n.KeywordStatement) and v4.values and v4.values[0] is not None
    value = int(_evaluate(v4.values[0], "v4", {}))
    assert value & 255 == int(_evaluate(v3.values[0], "v3", {}))
    assert value >> 8 == 0xFFF


@pytest.mark.parametrize("inputs", [0, 0x5A31C, 0xFFFFF, 0x000FF, 0x12300])
def test_input_byte_reads_the_v3_inputs(inputs: int) -> None:
    """v4 IN returns all 20 inputs of a NextMove PCI; (IN & 255) is what v3 IN returned."""
    migrated = migrate("x = IN\n", only=["S-IN"]).text
    statement = mintlang.parse(migrated, "v4").lines[0].statements[0]
    assert isinstance(statement, n.Assignment) and isinstance(statement.value, n.Parenthesised)
    masked = statement.value.expression
    assert isinstance(masked, n.Binary) and isinstance(masked.left, n.KeywordRef) and masked.left.keyword == "IN"
    assert isinstance(masked.right, n.Number)
    assert inputs & int(masked.right.value) == inputs & 0xFF  # v3:8927 inputs 0 to 7


@pytest.mark.parametrize("counts", [-2047, -1024, 0, 1, 1024, 2047])
def test_dac_counts_give_the_same_voltage(counts: int) -> None:
    """v3 -2047..2047 counts = -10..+10 V (v3:5943, v3:7126); v4 -100..100 % = -10..+10 V (v4:8750-8752)."""
    migrated = migrate(f"DAC.0 = {counts}\n", only=["S-DAC"]).text
    written = mintlang.parse(migrated, "v4").lines[0].statements[0]
    assert isinstance(written, n.KeywordStatement) and written.values and written.values[0] is not None
    volts = _evaluate(written.values[0], "v4", {}) * 10 / 100
    assert volts == pytest.approx(counts * 10 / 2047)


@pytest.mark.parametrize("percent", [-100, -50, 0, 12.5, 100])
def test_dac_read_gives_the_v3_counts(percent: float) -> None:
    migrated = migrate("x = DAC[0]\n", only=["S-DAC"]).text
    statement = mintlang.parse(migrated, "v4").lines[0].statements[0]
    assert isinstance(statement, n.Assignment)
    assert _evaluate(statement.value, "v4", {"DAC.0": percent}) == pytest.approx(percent * 2047 / 100)


# v3 MODE and ERROR values whose v4 bits all differ, so that a v4 state stands for one v3 state
# (1 and 6 share _mdTORQUE, 9 and 18 _mdFOLLOW); 5, 11 and 17 have no bit and are flagged. Each
# is written as a number and by its v3 name (v3:10040-10061, v3:4995-5010).
_MODES = {0: "_idle", 2: "_linear", 3: "_jog", 4: "_circular", 7: "_homing", 8: "_offset", 9: "_follow", 15: "", 16: ""}
_ERRORS = {0: "", 1: "_abort", 2: "_maxfe", 3: "_limit", 11: "_external"}
_MODE_TESTS = (
    "x = MODE.0 = {k}",
    "x = MODE.0 <> {k}",
    "x = 2 * (MODE.0 = {k}) + 1",
    "x = (MODE.0 = {k}) = 0",
    "x = (MODE.0 = {k}) AND (ERROR.0 = {e})",
    "IF MODE.0 = {k} THEN x = 1",
    "IF MODE.0 = {k} AND ERROR.0 = {e} THEN x = 1",
    "IF MODE.0 = {k} AND ERROR.0 <> {e} THEN x = 1",
    "IF MODE.0 = {k} OR ERROR.0 = {e} THEN x = 1",
    "WHILE NOT (MODE.0 = {k})",
    "PAUSE ERROR.0 = {e} OR MODE.0 = {k}",
)


def _state(mode: int, error: int) -> tuple[dict[str, float], dict[str, float]]:
    """The v3 names and the v4 names of one axis state: MODE/ERROR numbers, AXISMODE/AXISERROR bits."""
    db = mintlang.keyworddb.database()
    v4_constants = {name: constant.value for name, constant in db.constants.items()}

    def bits(table: Mapping[int, str], value: int) -> float:
        if not value:
            return 0
        first = table[value].strip("()").split(" | ")[0]  # one of the two limit bits is enough
        return v4_constants[first.upper()]

    v3 = {name: constant.value for name, constant in db.v3_constants.items()} | {"MODE.0": mode, "ERROR.0": error}
    v4 = v4_constants | {"AXISMODE.0": bits(MODE_BITS, mode), "AXISERROR.0": bits(ERROR_BITS, error)}
    return v3, v4


def _value_or_truth(statement: n.Statement, dialect: str, names: dict[str, float]) -> float:
    """An assignment's value; a condition's truth (IF, WHILE, PAUSE only ask zero or not)."""
    if isinstance(statement, n.Assignment):
        return _evaluate(statement.value, dialect, names)
    assert isinstance(statement, n.IfThen | n.While | n.Pause) and statement.condition is not None
    return float(bool(_evaluate(statement.condition, dialect, names)))


def _spellings(table: Mapping[int, str]) -> list[str]:
    return [spelling for value, name in table.items() for spelling in (str(value), name) if spelling]


@pytest.mark.parametrize("test", _MODE_TESTS)
def test_mode_and_error_tests_keep_their_v3_value(test: str) -> None:
    """A v3 comparison is 1 or 0 (v3:2009, v3:13999): used as a value, an operand of ``+`` or
    of the bitwise AND (v3:14033-14039), the migrated test gives that; in a condition, its truth."""
    states = [(mode, error, *_state(mode, error)) for mode in _MODES for error in _ERRORS]
    for written in sorted({test.format(k=k, e=e) + "\n" for k in _spellings(_MODES) for e in _spellings(_ERRORS)}):
        migrated = migrate(written, only=["M-CONST", "S-MODE", "S-ERROR"])
        assert migrated.manual == (), written
        v3_statement = mintlang.parse(written, "v3").lines[0].statements[0]
        v4_statement = mintlang.parse(migrated.text, "v4").lines[0].statements[0]
        for mode, error, v3_names, v4_names in states:
            v3 = _value_or_truth(v3_statement, "v3", v3_names)
            v4 = _value_or_truth(v4_statement, "v4", v4_names)
            assert v4 == v3, f"{written.strip()} -> {migrated.text.strip()}: MODE {mode}, ERROR {error}"
