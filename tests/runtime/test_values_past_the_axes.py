"""A write with more values than the axes it addresses is error 2017 when its line runs.

The guide: the values after the ``=`` cannot outnumber the axes given, except for a
circle (000:572-576, ``MOVEA[0,1] = 100,150,500`` is invalid); error 2017 is "Too many
parameters" (000:19047). This holds for every axis keyword, a parameter as much as a
move; a dot names one axis (000:677-681) and the default axes are those AXES lists
(000:605-618). Nothing is written when the statement fails: the handler reads the old
value.
"""

from __future__ import annotations

import pytest

from tests.runtime.running import simulate

HANDLER = 'END\n#ONERROR\nPRINT ERR, " ", ERL, " ", SPEED.0, " ", SPEED.1\nRETURN\n'


@pytest.mark.parametrize(
    "statement",
    [
        pytest.param("SPEED[0,1] = 7, 8, 9", id="brackets"),
        pytest.param("SPEED.0 = 7, 8", id="dot"),
        pytest.param("AXES[0,1]\nSPEED = 7, 8, 9", id="default-axes"),
        pytest.param("MOVEA.0 = 7, 8", id="a-move"),
    ],
)
def test_a_value_past_the_addressed_axes_is_error_2017_and_writes_nothing(statement: str) -> None:
    source = f"SPEED[0,1] = 5, 6\n{statement}\n"
    line = source.count("\n")
    result = simulate(source + HANDLER)
    assert result.terminal.startswith(f"2017 {line} 5 6\n")


def test_as_many_values_as_axes_are_written() -> None:
    # 000:636-640: with AXES[0,1,2], SPEED = ,10 sets axis 1 alone
    result = simulate("AXES[0,1,2]\nSPEED = 5, 6\nSPEED = ,10\nPRINT SPEED.0, SPEED.1\n")
    assert result.terminal == "510\n"
