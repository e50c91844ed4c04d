"""ECHO's bit 1 decides whether the controller shows its error messages on the terminal.

Bit 1 of ECHO set displays error messages on the terminal (000:9549), and ``ECHO = 0`` leaves only what the
program itself prints (000:9560-9562); its power-up value, 7, has every bit set (000:9538-9540). Without a
``#ONERROR`` the controller prints an error's message as the program stops (000:4580, 4605-4606): with
bit 1 clear that message is not shown, and the program stops all the same. mint-run printed it whatever
ECHO held. The reason the run stopped still goes to stderr and the report, which are the simulator's.
"""

from __future__ import annotations

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate


@pytest.mark.parametrize("echo", [0, 1, 4, 5])
def test_without_bit_1_the_error_message_is_not_shown(echo: int) -> None:
    result = simulate(f'ECHO = {echo}\nPRINT "data"\nSCALE = -3\nPRINT "never"\n')
    assert result.terminal == "data\n"
    assert result.stop.reason is StopReason.ERROR
    assert result.err == 3
    assert "R0003" in result.stop.message


@pytest.mark.parametrize("echo", ["", "ECHO = 2\n", "ECHO = 7\n"])
def test_with_bit_1_the_error_message_ends_the_output(echo: str) -> None:
    result = simulate(f'{echo}PRINT "data"\nSCALE = -3\n')
    assert result.terminal.startswith("data\nR0003: PROGRAM Data specified out of range")


def test_an_echo_the_configuration_file_sets_hides_the_program_s_compile_error() -> None:
    # the configuration file runs before the program is compiled (000:269-271)
    result = simulate("PRINT 1 +\n", config="RESETALL\nECHO = 0\n")
    assert result.terminal == ""
    assert result.stop.reason is StopReason.ERROR
    assert result.err == 2003
