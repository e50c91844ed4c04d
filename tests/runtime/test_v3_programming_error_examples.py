"""The v3 guide's examples of its programming errors end a v3 run with the message the guide files them under.

Chapter 11 gives one or two lines for each message (001:12916-13186); a run of
such a line stops on it with ``ERROR: Program: <message> at line <n>`` (and ``on axis <n>``
when the error names one).
"""

from __future__ import annotations

import pytest

from mintlang.runtime.run import run_source
from mintlang.runtime.scenario import Scenario
from mintlang.runtime.scenario.stimulus import DrivesEnabled

ENABLED = Scenario(drives=(DrivesEnabled(),))


def test_an_assignment_with_no_expression_is_refused_before_the_program_runs() -> None:
    # the statement cannot be compiled, as a syntax error cannot: nothing before it runs
    result = run_source('PRINT "before"\nDIM t(3)\nt(2) =\n', dialect="v3")
    assert result.terminal == "ERROR: Program: No expression at line 3\n"


@pytest.mark.parametrize(
    ("lines", "message"),
    [
        pytest.param("avar =", "No expression at line 1", id="001:12957-12964 an assignment but no expression"),
        pytest.param("a = FLY", "Write only at line 1", id="001:13073-13080 a read of a write only keyword"),
        pytest.param("a = EO", "Write only at line 1", id="001:7504 ECHO's table marks it written, not read"),
        pytest.param("a = STOP", "Read only or Command at line 1", id="001:13083-13094 a read of a command"),
        pytest.param("A1 = 10", "Read only or Command at line 1", id="001:13083-13091 a write to a read only one"),
        pytest.param("a = 0\nSF[a+1] = 1000", "Invalid axis at line 2", id="001:13184 an expression as an axis"),
        pytest.param("a = 0\nMOVER[a+1] = 100", "Invalid axis at line 2", id="001:1009-1011 the same, by 3.3"),
        pytest.param("DIM t(2) = 1,1\nSF[t(1)] = 1000", "Invalid axis at line 2", id="001:13175 an array element"),
        pytest.param("a = 0\nPRINT POS[a+1]", "Invalid axis at line 2", id="001:13175 read"),
        pytest.param("VR[0] = 100", "Invalid axis at line 1 on axis 0", id="001:13183 a vector move on one axis"),
        pytest.param("VECTORA.1 = 100", "Invalid axis at line 1 on axis 1", id="001:3257 vectors need two axes"),
        pytest.param("VR[0,1] = 100", "Invalid axis at line 1 on axis 0", id="001:13175 one position moves one axis"),
    ],
)
def test_each_example_stops_the_run_with_its_message(lines: str, message: str) -> None:
    result = run_source(f"{lines}\n", dialect="v3", scenario=ENABLED)
    assert result.terminal == f"ERROR: Program: {message}\n"


def test_invalid_axis_is_system_error_4_in_onerror() -> None:
    # 001:4918-4925: "Invalid axis" is ERR 4, which #ONERROR traps; RETURN goes on after the line
    program = 'a = 0\nSF[a+1] = 1000\nPRINT "next"\nEND\n#ONERROR\nPRINT "ERR ", ERR\nRETURN\n'
    assert run_source(program, dialect="v3").terminal == "ERR 4\nnext\n"


def test_a_number_or_a_variable_is_an_axis() -> None:
    # 001:1005-1007: MOVER[a] = 100 is valid; a vector move on two axes runs
    program = "a = 1\nSF[a] = 2\nVR[0,1] = 10,10 : GO[0,1]\nPAUSE IDLE[0,1]\nPRINT SF.1, POS.0\n"
    assert run_source(program, dialect="v3", scenario=ENABLED).terminal == "210\n"
