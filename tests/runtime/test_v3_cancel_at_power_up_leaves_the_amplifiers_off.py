"""Mint v3's CANCEL recovers the amplifiers a motion error switched off, but not those off since power-up.

The amplifier enable keeps the amplifiers disabled from power-up until a RESET or CONFIG (001:11409-11411);
ENABLE = 1 switches it on too (001:7567-7576). After a motion error shut the system down, RESET or CANCEL
recovers it (001:5004-5006), and the guide's handler goes on moving after CANCEL : RETURN (001:5037-5066).
"""

from __future__ import annotations

from mintlang.runtime.run import run_source


def test_cancel_at_power_up_leaves_the_amplifiers_disabled() -> None:
    result = run_source("CANCEL\nMOVEA.0 = 10 : GO.0\n", dialect="v3")
    assert result.terminal == "ERROR: Program: Servo off at line 2 on axis 0\n"


def test_enable_0_at_power_up_switches_nothing_on_for_cancel() -> None:
    result = run_source("ENABLE = 0\nCANCEL\nMOVEA.0 = 10 : GO.0\n", dialect="v3")
    assert result.terminal == "ERROR: Program: Servo off at line 3 on axis 0\n"


def test_dislimit_at_power_up_leaves_them_disabled_too() -> None:
    # DISLIMIT issues a CANCEL (001:5070)
    result = run_source("DISLIMIT\nMOVEA.0 = 10 : GO.0\n", dialect="v3")
    assert result.terminal == "ERROR: Program: Servo off at line 2 on axis 0\n"


def test_cancel_after_a_motion_error_switches_them_on_again() -> None:
    # ABORT is a motion error (ERROR 1, 001:4995-5006) that switches the enable off; CANCEL : RETURN moves on
    program = "RESET\nABORT\nMOVEA.0 = 10 : GO.0 : PAUSE IDLE.0\nPRINT POS.0\nEND\n#ONERROR\nCANCEL\nRETURN\n"
    assert run_source(program, dialect="v3").terminal == "10\n"


def test_enable_switches_them_on_before_any_reset() -> None:
    program = "ENABLE = 1\nCANCEL\nMOVEA.0 = 10 : GO.0 : PAUSE IDLE.0\nPRINT POS.0\n"
    assert run_source(program, dialect="v3").terminal == "10\n"
