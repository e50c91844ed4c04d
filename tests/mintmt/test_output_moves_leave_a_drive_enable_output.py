"""An output a drive enable is assigned to (DRIVEENABLEOUTPUT) follows DRIVEENABLE, errors and RESET, and setting it
by hand does not change it (000:14935-14939, 9281-9286; spec IO-3 RC: such writes are ignored). The move buffer's
output moves set outputs as OUT does (004:288-304, MT-22), so they leave it as well, and set the others as usual:
they turned a drive's enable output off behind its drive."""

from __future__ import annotations

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import Limits, run_source
from mintlang.runtime.scenario import DrivesEnabled, Scenario

_ENABLED = Scenario(drives=(DrivesEnabled(),))
# output 2 enables axis 1's drive: DRIVEENABLE(1) = 1 turns it on, OUT reads 4 (2 to the power 2)
_OWNED = "DRIVEENABLEOUTPUT(1) = 2\nDRIVEENABLE(1) = 1\nMOVEBUFFERSIZE(0) = 4\n"


def _outputs(moves: str) -> int:
    source = f"{_OWNED}{moves}GO(0)\nWAIT = 100\n"
    result = run_source(source, dialect="mintmt", scenario=_ENABLED, limits=Limits(until_ms=1000, max_wall_s=60.0))
    assert result.stop.reason is StopReason.END
    return result.outputs


@pytest.mark.parametrize(
    ("moves", "outputs"),
    [
        # the bank's pattern 1 sets output 0 and clears the others but output 2: 1 + 4
        pytest.param("MOVEOUT(0,0) = 1\n", 5, id="moveout"),
        pytest.param("MOVEOUTX(0,2) = 0\nMOVEOUTX(0,3) = 1\n", 4 + 8, id="moveoutx"),
        # a pulse of 10 ms on output 2 neither turns it off at its end nor on at its start: still 4
        pytest.param("MOVEPULSEOUTX(0,2) = 10\n", 4, id="movepulseoutx"),
    ],
)
def test_an_output_move_leaves_a_drives_enable_output(moves: str, outputs: int) -> None:
    assert _outputs(moves) == outputs


def test_a_pulse_does_not_turn_on_a_disabled_drives_output() -> None:
    # DRIVEENABLE(1) = 0 turns output 2 off; 100 ms into a pulse of 500 ms on it, it is still off: 0
    assert _outputs("DRIVEENABLE(1) = 0\nMOVEPULSEOUTX(0,2) = 500\n") == 0
