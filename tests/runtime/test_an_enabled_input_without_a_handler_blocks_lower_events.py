"""An input IMASK enables whose ``#INx`` the program lacks holds back every lower-priority event.

The guide warns that an input enabled to raise events without its handler in the program stops the
lower-priority events from occurring (000:5057-5059). Such an input is pending all the same: IPEND
shows active inputs whose handlers are not called, and a bit with no handler stays set until it is
written clear (000:12621-12630). ``#IN0`` ranks highest among the inputs (000:5062), and ``#COMMSx``
ranks below every input (EV-2). IMASK enables every input at power-up (65535 on a NextMove BX).
"""

from __future__ import annotations

import pytest

from mintlang.runtime.comms.packets import encode_write
from mintlang.runtime.run import run_source
from mintlang.runtime.scenario.stimulus import HostPacket, Scenario
from mintlang.runtime.simulation import Limits
from tests.runtime.running import simulate

# Input 1 turns active at 100 ms (a level input, as INPUTMODE leaves it) and has no handler;
# input 3, edge triggered on its rising edge, turns active at 150 ms.
_INPUT_3_AFTER_AN_UNHANDLED_INPUT_1 = """REM @sim input 1 1 at 100
REM @sim input 3 1 at 150
DIM calls = 0
INPUTMODE = 8
INPUTPOSTRIGGER = 8
{mask}WAIT = 300
PRINT calls
END
#IN3
calls = calls + 1
RETURN
"""


@pytest.mark.parametrize(
    ("mask", "calls"),
    [
        pytest.param("", 0, id="input 1 enabled: #IN3 never runs"),
        pytest.param("IMASK = 65533\n", 1, id="input 1 masked off: #IN3 runs once"),
    ],
)
def test_an_enabled_input_without_a_handler_holds_back_lower_inputs(mask: str, calls: int) -> None:
    source = _INPUT_3_AFTER_AN_UNHANDLED_INPUT_1.format(mask=mask)
    assert simulate(source).terminal == f"{calls}\n"


def test_a_higher_priority_input_still_runs() -> None:
    # input 3 has no handler and is active first; #IN1 ranks above it, so its edge at 150 ms is served
    source = """REM @sim input 3 1 at 100
REM @sim input 1 1 at 150
DIM calls = 0
INPUTMODE = 2
INPUTPOSTRIGGER = 2
WAIT = 300
PRINT calls
END
#IN1
calls = calls + 1
RETURN
"""
    assert simulate(source).terminal == "1\n"


def test_comms_events_are_held_back_too() -> None:
    # the host writes comms location 3 at 200 ms, while input 1, without a handler, is active
    source = """REM @sim input 1 1 at 100
DIM calls = 0
WAIT = 300
PRINT calls
END
#COMMS3
calls = calls + 1
RETURN
"""
    packet = HostPacket(200, encode_write(2, 3, [42]))
    assert simulate(source, scenario=Scenario(host_packets=(packet,))).terminal == "0\n"


def test_writing_the_unhandled_bit_clear_lets_the_held_events_run() -> None:
    # both inputs edge triggered: input 1's edge at 100 ms (no handler) and input 3's at 150 ms are both pending
    # at 200 ms (IPEND 2 + 8); clearing input 1's bit lets #IN3 run, which clears its own
    source = """REM @sim input 1 1 at 100
REM @sim input 3 1 at 150
DIM calls = 0
INPUTMODE = 10
INPUTPOSTRIGGER = 10
WAIT = 200
PRINT calls, " ", IPEND
IPEND = 8
WAIT = 10
PRINT calls, " ", IPEND
END
#IN3
calls = calls + 1
RETURN
"""
    assert simulate(source).terminal == "0 10\n1 0\n"


def test_mint_v3_holds_nothing_back_for_a_bit_ipend_sets() -> None:
    # the v3 guide says nothing of it (runtime/BEHAVIOUR.md): IPEND = 128 sets #IN7's bit, the highest in v3
    # (001:2574-2583), with no #IN7; input 3's falling edge at 150 ms still calls #IN3, and the bit stays (128)
    source = """REM @sim input 3 1 at 100
REM @sim input 3 0 at 150
IPEND = 128
WAIT = 300
PRINT IPEND
END
#IN3
PRINT "in3"
RETURN
"""
    result = run_source(source, dialect="v3", limits=Limits(until_ms=60_000, max_wall_s=60.0))
    assert result.terminal == "in3\n128\n"
