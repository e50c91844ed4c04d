"""S-INEDGE: inputs without a handler that v4 serves before a handler's input are masked off with IMASK.

v3 calls #INn for the inputs that have one and IMASK only masks handlers off (001:8894-8902). In v4 #IN0
is served first (000:5062-5064), and an input IMASK enables that has no handler holds back every event of a
lower priority (000:5055-5057): with #IN3 alone, input 2 used as a plain switch kept #IN3 from ever running.
IMASK keeps those inputs' bits clear; the others keep v4's default of all ones (000:11896-11900).
"""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate
from mintlang.migrate.verification import Verdict, verify
from mintlang.runtime.scenario import InputLevel, Scenario

PROGRAM = 'r = 0\nPAUSE IN4 = 1\nPRINT "rejects ", r\nEND\n#IN3\n  r = r + 1\nRETURN\n'


@pytest.mark.parametrize(
    ("controller", "line"),
    [("nextmove-pci", "IMASK = IMASK & 0xFFFF8"), ("mintdrive", "IMASK = IMASK & 0x3FFF8")],
)
def test_the_inputs_before_a_handler_are_masked_off(controller: str, line: str) -> None:
    result = migrate(PROGRAM, controller=controller)
    assert f"\n{line}\n" in result.text
    assert migrate(result.text, controller=controller).text == result.text


def test_no_input_is_masked_where_none_comes_before_a_handler() -> None:
    assert "IMASK" not in migrate("LOOP : ENDL\n#IN0\nRETURN\n#IN1\nRETURN\n").text


def test_a_switch_on_input_2_no_longer_holds_back_the_handler_of_input_3() -> None:
    switch_then_reject = (
        InputLevel(time_ms=100, channel=2, level=1),
        InputLevel(time_ms=200, channel=2, level=0),
        InputLevel(time_ms=300, channel=3, level=1),
        InputLevel(time_ms=400, channel=3, level=0),  # the falling edge v3 calls #IN3 on (001:2525)
        InputLevel(time_ms=500, channel=4, level=1),
    )
    found = verify(migrate(PROGRAM), scenario=Scenario(inputs=switch_then_reject), until_ms=1000)
    assert found.verdict is Verdict.EQUIVALENT


def test_an_imask_the_program_writes_leaves_those_inputs_off() -> None:
    # v3's IMASK = 000001111 kept #IN0..#IN3 on (001:8896-8902); only #IN3 exists, so inputs 0..2 stay off
    result = migrate("IMASK = 000001111\n" + PROGRAM, only=["S-IMASK"])
    assert result.text.startswith("IMASK = (000001111 & 0xF8) | 0xFFF00\n")


def test_an_imask_the_program_ors_in_leaves_those_inputs_off() -> None:
    # the v3 guide enables an input with IMASK = IMASK OR 0100 (001:4222); input 2 has no handler here
    result = migrate("IMASK = IMASK OR 0100\n" + PROGRAM, only=["S-IMASK"])
    assert result.text.startswith("IMASK = IMASK OR (0100 & 0xF8)\n")
