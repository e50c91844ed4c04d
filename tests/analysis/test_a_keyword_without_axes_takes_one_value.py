"""A keyword that names no axis or channel takes one value a write: a second is error 2017, checked and run.

TIMEREVENT (000:16777), WAIT (000:17324), TERMINAL (000:16667) and BANK (000:7326) write one
``<expression>`` and address nothing, while the values after the ``=`` may not outnumber what they go to
(000:572-574), "Too many parameters" being error 2017 (000:19047), as for a channel keyword
(tests/runtime/test_a_channel_keyword_takes_one_value.py). ``WAIT = 10, 20`` passed mint check, and the
run waited 10 ms and went on.
"""

from __future__ import annotations

import pytest

from mintlang.runtime.run import run_source
from tests.analysis.placed import placed

HANDLER = "END\n#ONERROR\nPRINT ERR\nRETURN\n"


@pytest.mark.parametrize(
    ("line", "second"),
    [
        pytest.param("TIMEREVENT = 100, 200", "200", id="TIMEREVENT"),
        pytest.param("WAIT = 10, 20", "20", id="WAIT"),
        pytest.param("TERMINAL = 1, 2", "2", id="TERMINAL"),
        pytest.param("BANK = 1, 2", "2", id="BANK"),
        pytest.param("TIME = , 5", "5", id="a skipped place"),
    ],
)
def test_a_second_value_is_too_many_parameters(line: str, second: str) -> None:
    assert placed(line + "\n", "code", "text") == [("E2017", second)]
    assert run_source(f"{line}\n{HANDLER}", controller="nextmove-pci").terminal.startswith("2017\n")


@pytest.mark.parametrize(
    "line",
    [
        pytest.param("TIMEREVENT = 100", id="one value"),
        pytest.param("TIME = 1;", id="a fill is one value"),
        pytest.param("DIM b(3) = 1, 2, 3", id="an array's values"),
    ],
)
def test_one_value_is_no_error(line: str) -> None:
    assert placed(line + "\n", "code", "text", codes="E2017") == []
