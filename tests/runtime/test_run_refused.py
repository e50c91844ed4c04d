"""``RunResult.refused`` tells a program the controller's compiler rejected from one that ran and failed.

A compile error stops the run before the program's first statement (000:269-271;
in v3 a variable read before anything declares it, 001:1352-1367); an error a line
raises when it runs is the program's own doing. ``mint-migrate --verify`` needs the
difference: an original that never ran has no behaviour to compare.
"""

from __future__ import annotations

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import run_source


@pytest.mark.parametrize(
    ("program", "dialect"),
    [
        pytest.param("PRINT 1\nx = 2\n", "v4", id="v4 undeclared variable (3001)"),
        pytest.param("LOOP\nPRINT 1\n", "v4", id="v4 loop without ENDL"),
        pytest.param("PRINT 1\nPRINT b\nb = 2\n", "v3", id="v3 variable read before anything declares it"),
    ],
)
def test_a_program_its_compiler_rejects_is_refused_and_prints_nothing_of_its_own(program: str, dialect: str) -> None:
    result = run_source(program, dialect=dialect)
    assert result.refused
    assert result.stop.reason is StopReason.ERROR
    assert not result.terminal.startswith("1")  # its first PRINT never ran


@pytest.mark.parametrize(
    ("program", "dialect"),
    [
        pytest.param("DIM a(2)\nPRINT 1\nPRINT a(5)\n", "v4", id="v4 index out of range when the line runs"),
        pytest.param("PRINT 1\nRETURN\n", "v3", id="v3 RETURN without GOSUB"),
        pytest.param("PRINT 1\n", "v4", id="a program that ends"),
    ],
)
def test_a_program_that_ran_is_not_refused_whatever_stopped_it(program: str, dialect: str) -> None:
    result = run_source(program, dialect=dialect)
    assert not result.refused
    assert result.terminal.startswith("1")
