"""A dot names one axis or one channel: a second number after it is a syntax error, in mint check and mint-run.

The guide references a single axis with a dot followed by the axis number (000:678-679), and a channel
keyword takes its one channel only that way (000:560, 702-705); several axes are listed in square
brackets (000:563-566), and a channel keyword addresses one channel per call, never several
(000:548-549). Only the CAN keywords chain two dot values, bus and node (``REMOTEIN.2.65``, 000:18607).
``POS.1.5`` is therefore not written as POS's format allows (``v = POS[axis]``), which is 2003 "Syntax
error" (000:18920-18924), as an addressing the format does not show is for ``TIME.5`` and ``ADC[1]``
(000:705-708). mint check let it pass, and mint-run read ``POS.1.5`` as ``POS[1,5]`` (the two positions
ANDed) and ``OUT.1.5 = 1`` as ``OUT.1 = 1``; a channel glued to its keyword (``OUT1``, 000:1114) and a dot
after it (``OUT1.2``) named the channel twice, and the dot was dropped.
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.checking import ERROR, covered, found, only
from tests.runtime.running import assert_syntax_error_before_it_runs

SECOND_NUMBERS = [
    pytest.param("a = POS.1.5", ".5", id="axis-read"),
    pytest.param("SPEED.0.1 = 10", ".1", id="axis-write"),
    pytest.param("a = POS.1.(a)", ".(a)", id="axis-expression"),
    pytest.param("a = IN.1.5", ".5", id="channel-read"),
    pytest.param("OUT.1.5 = 1", ".5", id="channel-write"),
    pytest.param("OUT1.2 = 1", ".2", id="glued-channel"),
    pytest.param("a = INKEY.1.2", ".2", id="terminal"),
]


@pytest.mark.parametrize(("line", "second"), SECOND_NUMBERS)
def test_mint_check_reports_the_second_number(line: str, second: str) -> None:
    source = f"DIM a\n{line}\nPRINT a\n"
    assert found(source, controller="nextmove-bx") == [("E2003", ERROR, 2)]
    assert covered(source, only(source, "E2003", controller="nextmove-bx")) == second


@pytest.mark.parametrize(("line", "second"), SECOND_NUMBERS)
def test_mint_run_stops_before_the_program_starts(line: str, second: str) -> None:
    assert_syntax_error_before_it_runs(line)


@pytest.mark.parametrize(
    "line",
    ["a = POS.1", "a = POS.(a + 1)", "OUT.1 = 1", "OUT1 = 1", "a = INKEY.1", "a = REMOTEIN.1.2"],
)
def test_one_number_after_the_dot_and_the_can_bus_and_node_pass(line: str) -> None:
    assert found(f"DIM a\n{line}\nPRINT a\n", controller="nextmove-bx") == []


@pytest.mark.parametrize(
    ("source", "says"),
    [
        pytest.param("a = POS.1.5\n", "POS takes one axis number after its dot (several axes are listed in brackets)"),
        pytest.param("OUT.1.5 = 1\n", "OUT takes one channel number after its dot"),
    ],
)
def test_the_message_names_what_the_dot_addresses(source: str, says: str) -> None:
    """Axes may be listed in brackets (000:563-566); a channel keyword's channels may not (000:548-549)."""
    [diagnostic] = [d for d in mintlang.check(source) if d.code == "E2003"]
    assert diagnostic.message.endswith(says)
