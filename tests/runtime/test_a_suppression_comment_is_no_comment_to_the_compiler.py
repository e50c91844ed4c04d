"""A ``mint: ignore`` comment silences the checker, not the controller: its compiler reads a REM as a remark and
still refuses the program (``mint check --add-ignore`` writes such comments into running programs).

An undeclared variable is a compile error, #3001 "Variable undefined, use DIM" (000:19073-19080), found before
any line runs (000:4563-4568); the same program with the error silenced for the checker stops just so.
"""

from __future__ import annotations

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate


@pytest.mark.parametrize(
    "program",
    [
        pytest.param('PRINT "before"\nPRINT b\n', id="no-comment"),
        pytest.param('PRINT "before"\nPRINT b : REM mint: ignore[E3001]\n', id="silenced-on-its-line"),
        pytest.param('REM mint: ignore-file[E3001]\nPRINT "before"\nPRINT b\n', id="silenced-in-the-file"),
    ],
)
def test_an_undeclared_variable_stops_the_program_before_it_runs(program: str) -> None:
    result = simulate(program)
    assert (result.stop.reason, "before" in result.terminal) == (StopReason.ERROR, False)
    assert result.terminal.startswith("C3001: PROGRAM Variable undefined, use DIM")
