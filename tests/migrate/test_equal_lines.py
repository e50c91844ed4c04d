"""Two lines of the same text are two places: each gets its own rewrite or manual item.

The parser shares one syntax object between equal lines, so a rule that named a
statement by its syntax (its ``id()`` or its value) would rewrite one of them,
or pair a statement with the neighbour of the other. These are the rules that
look at what encloses an expression (``mintlang.syntax.parents``) or at the
statement next to another on its line (``Context.neighbours``), each on a line
written twice.
"""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate
from tests.migrate.helpers import flagged, one_rule, rewritten

_REWRITES = [
    pytest.param("S-ACCEL", "ACCEL = 100\n", "ACCEL = 100 : DECEL = 100\n", id="accel-gets-decel"),
    pytest.param("S-ACCEL", "ACCEL = 5 : DECEL = 5\n", "ACCEL = 5 : DECEL = 5\n", id="accel-own-output"),
    pytest.param("S-OFFSET", "OFFSET.1 = 10\n", "OFFSET.1 = 10 : GO.1\n", id="offset-gets-go"),
    pytest.param("S-OFFSET", "OFFSET.1 = 10 : GO.1\n", "OFFSET.1 = 10 : GO.1\n", id="offset-own-output"),
    pytest.param("S-IDLEAXES", "MOVEA = 10 : GO\n", "MOVEA[0] = 10 : GO[0]\n", id="go-after-its-move"),
    pytest.param("M-TRIG", "x = SIN 90 + a\n", "x = (SIN(90) * 1000) + a\n", id="trig"),
    pytest.param("M-TRIG", "x = (SIN(30) * 1000)\n", "x = (SIN(30) * 1000)\n", id="trig-own-output"),
    pytest.param("M-TILDE", "OUT = ~OUT\n", "OUT = (~OUT & 255)\n", id="tilde"),
    pytest.param(
        "M-PREC", "IF a = 1 AND b = 2 OR c THEN d = 1\n", "IF (a = 1 AND b = 2) OR c THEN d = 1\n", id="precedence"
    ),
    pytest.param("S-MODE", "IF MODE = _jog THEN x = 1\n", "IF (AXISMODE & _mdJOG) THEN x = 1\n", id="mode-truth"),
    pytest.param("S-IN", "JOG = IN\n", "JOG = (IN & 255)\n", id="in-byte"),
    pytest.param("S-IN", "IF IN & 15 THEN x = 1\n", "IF IN & 15 THEN x = 1\n", id="in-masked"),
    pytest.param("S-IMASK", "x = IMASK\n", "x = (IMASK & 255)\n", id="imask-read"),
    pytest.param("S-DAC", "x = DAC[1]\n", "x = (DAC.1 * 2047 / 100)\n", id="dac-read"),
    pytest.param("S-DAC", "x = (DAC.1 * 2047 / 100)\n", "x = (DAC.1 * 2047 / 100)\n", id="dac-own-output"),
]

_FLAGS = [
    pytest.param("S-MODE", "x = MODE\n", id="mode-value"),
    pytest.param("X-ERR", "IF (ERR) >= 10 THEN x = 1\n", id="err-compared"),
]


@pytest.mark.parametrize(("rule", "line", "expected"), _REWRITES)
def test_each_of_two_equal_lines_is_rewritten(rule: str, line: str, expected: str) -> None:
    assert rewritten(rule, line * 2) == expected * 2


@pytest.mark.parametrize(("rule", "source"), _FLAGS)
def test_each_of_two_equal_lines_gets_its_manual_item(rule: str, source: str) -> None:
    once = flagged(rule, source)
    assert once and flagged(rule, source * 2) == once * 2


def test_each_of_two_equal_analogue_reads_is_converted_and_flagged() -> None:
    result = one_rule("S-ANALOG", "y = 2 * (A1)\ny = 2 * (A1)\n")
    assert result.text.count("y = 2 * (INT((ADC.0 + 100) * 1024 / 200) - (ADC.0 >= 100))\n") == 2
    assert [item.line for item in result.manual] == [2, 4]


def test_two_equal_accel_lines_both_get_decel_in_a_whole_migration() -> None:
    result = migrate("ACCEL = 100\nACCEL = 100\n")
    assert result.text.endswith("ACCEL = 100 : DECEL = 100\nACCEL = 100 : DECEL = 100\n")
    assert result.manual == ()
