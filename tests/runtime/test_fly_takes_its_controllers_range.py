"""FLY's slave distance takes its attributes table's range for the controller, after SCALE as a scaled
value (000:10500-10510, 5647-5648): -8388607 to 8388607 on NextMove, -32767 to 32767 on MintDrive and
ServoNode 51; outside it is error 3 (000:18518-18521) and nothing is loaded, as mint check says."""

from __future__ import annotations

import pytest

from tests.runtime.running import simulate

HANDLER = 'END\n#ONERROR\nPRINT ERR, " ", ERRAXIS, " ", AXISMODE.0\nRETURN\n'
FLY = "MASTERSOURCE.0 = _msSPEED\nFLY.0 = {value}\n"


@pytest.mark.parametrize("controller", ["mintdrive", "servonode51"])
def test_a_distance_past_32767_is_out_of_range_on_the_drives(controller: str) -> None:
    result = simulate(FLY.format(value=32768) + HANDLER, controller=controller)
    assert result.terminal == "3 0 0\n"


@pytest.mark.parametrize("controller", ["mintdrive", "servonode51"])
def test_32767_is_in_range_on_the_drives(controller: str) -> None:
    result = simulate(FLY.format(value=-32767) + 'PRINT "loaded"\n' + HANDLER, controller=controller)
    assert result.terminal == "loaded\n"


def test_the_range_is_for_the_counts_after_scale() -> None:
    # 4000 user units at SCALE 10 are 40000 counts, past 32767 (000:5647-5648)
    result = simulate("SCALE.0 = 10\n" + FLY.format(value=4000) + HANDLER, controller="mintdrive")
    assert result.terminal == "3 0 0\n"


def test_nextmove_takes_a_distance_the_drives_refuse() -> None:
    result = simulate("MASTERCHANNEL.0 = 1\nFLY.0 = 40000\nPRINT AXISMODE.0\n" + HANDLER, controller="nextmove-bx")
    assert result.terminal == "0\n"  # loaded, waiting for GO: no mode yet (000:11058-11074)
