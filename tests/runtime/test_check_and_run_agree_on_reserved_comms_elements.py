"""mint check and mint-run judge alike a COMMS element the extended map reserves.

Of each axis's 15 locations only offsets 0 to 7 hold a parameter; 8 to 14 are reserved (000:2610), and so
are the I/O block's offsets 1, 3 and 18 to 34 (000:2621, 2624, 2664-2667). Reading or writing one is error 46,
"COMMS element is reserved" (000:18679-18680, "tried accessing"), which the run raised and the check passed.
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.placed import placed_codes
from tests.runtime.running import simulate

HANDLER = 'END\n#ONERROR\nPRINT "ERR ", ERR, " ERL ", ERL\nRETURN\n'


@pytest.mark.parametrize(
    ("line", "column"),
    [
        pytest.param("PRINT COMMS(108)", 13, id="read-axis-0-offset-8"),
        pytest.param("PRINT COMMS(219)", 13, id="read-axis-7-offset-14"),
        pytest.param("PRINT COMMS(221)", 13, id="read-io-offset-1"),
        pytest.param("PRINT COMMS(223)", 13, id="read-io-offset-3"),
        pytest.param("PRINT COMMS(238)", 13, id="read-io-offset-18"),
        pytest.param("PRINT COMMS(254)", 13, id="read-io-offset-34"),
        pytest.param("COMMS(114) = 1", 7, id="write-axis-0-offset-14"),
        pytest.param("COMMS(240) = 1", 7, id="write-io-offset-20"),
    ],
)
def test_both_tools_give_error_46_at_the_element(line: str, column: int) -> None:
    assert placed_codes(line + "\n") == [("E0046", 1, column)]
    result = simulate(f'{line}\nPRINT "after"\n' + HANDLER)
    assert result.terminal.startswith("ERR 46 ERL 1\n")


@pytest.mark.parametrize(
    "line",
    [
        pytest.param("PRINT COMMS(107)", id="axis-0-following-error"),
        pytest.param("PRINT COMMS(222)", id="digital-outputs"),
        pytest.param("PRINT COMMS(239)", id="build-number"),
        pytest.param("COMMS(99) = 1", id="general-element"),
    ],
)
def test_both_tools_pass_a_mapped_element(line: str) -> None:
    assert placed_codes(line + "\n") == []
    assert simulate(f'{line}\nPRINT "after"\n').terminal.endswith("after\n")


def test_mintmt_keeps_the_reserved_elements_of_v4() -> None:
    # MT-1: MintMT keeps v4's extended map, as it does for the read-only elements (error 45)
    (diagnostic,) = mintlang.check_application("Print comms(108)\n", dialect="mintmt").program
    assert diagnostic.code == "E0046"
