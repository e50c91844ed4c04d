"""The v3 guide's examples of its programming errors end a v3 run with the message the guide files them under.

Chapter 11 gives one or two lines for each message (001:12916-13186); a run of
such a line stops on it with ``ERROR: Program: <message> at line <n>``.
"""

from __future__ import annotations

import pytest

from mintlang.runtime.run import run_source


@pytest.mark.parametrize(
    ("line", "message"),
    [
        pytest.param("avar =", "No expression", id="001:12957-12964 an assignment but no expression"),
        pytest.param("a = FLY", "Write only", id="001:13073-13080 a read of a write only keyword"),
        pytest.param("a = STOP", "Read only or Command", id="001:13083-13094 a read of a command"),
        pytest.param("A1 = 10", "Read only or Command", id="001:13083-13091 a write to a read only keyword"),
    ],
)
def test_each_example_stops_with_its_message(line: str, message: str) -> None:
    result = run_source(f"{line}\n", dialect="v3")
    assert result.terminal == f"ERROR: Program: {message} at line 1\n"


def test_an_assignment_with_no_expression_is_refused_before_the_program_runs() -> None:
    # the statement cannot be compiled, as a syntax error cannot: nothing before it runs
    result = run_source('PRINT "before"\nDIM t(3)\nt(2) =\n', dialect="v3")
    assert result.terminal == "ERROR: Program: No expression at line 3\n"
