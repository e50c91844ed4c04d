"""Mint v3's DEFAULT does what RESET does and more: the guide tells the two apart only by the parameters RESET
leaves (ACCEL, BACKOFF, CONFIG, CURRLIMIT, ERRORIN, ... SPEED, WRAP; 001:7244-7251), and calls DEFAULT switching
the controller off and on again (001:7244). So what RESET's table resets, DEFAULT resets too: the outputs
cleared, TIME 0, IMASK 255, contouring off, the limits watched (001:11427-11444), besides the power-up values.
"""

from __future__ import annotations

from mintlang.runtime.run import run_source


def test_default_clears_the_outputs_time_and_imask_as_reset_does() -> None:
    # OUT cleared and TIME 0 (001:11440, 11442), IMASK 255 (001:11438): the PRINT runs within the 2 ms TIME counts in
    program = 'OUT = 5 : IMASK = 3 : WAIT = 20\nDEFAULT\nPRINT OUT, " ", IMASK, " ", TIME\n'
    assert run_source(program, dialect="v3").terminal == "0 255 0\n"


def test_default_of_one_axis_clears_the_outputs_too() -> None:
    # RESET clears the outputs whatever axis it names (001:11409); DEFAULT[1] does as much
    assert run_source("OUT = 5\nDEFAULT[1]\nPRINT OUT\n", dialect="v3").terminal == "0\n"
