"""Encoder and DAC keywords number channels, not axes: one the controller lacks is error 4 in both tools.

The dot-parameter table gives a NextMove BX axes 0 to 7 but DAC and encoder channels 0 to 3, and a
MintDrive axis 0 and encoder channel 0 (000:5613, 5621, 5624). ENCODER, ENCODERVEL, ENCODERSCALE and
ENCODERWRAP are addressed by encoder channel, DAC and DACLIMITMAX by DAC output channel (000:9601, 9719,
9760, 9803, 8729, 8808). A channel the controller does not have is #4, "Channel out of range"; #2 is
for an axis (000:18514-18525).
"""

from __future__ import annotations

import pytest

import mintlang
from tests.runtime.running import simulate

HANDLER = 'END\n#ONERROR\nPRINT "ERR ", ERR, " ERL ", ERL\nRETURN\n'


@pytest.mark.parametrize(
    ("controller", "line"),
    [
        pytest.param("nextmove-bx", "PRINT ENCODER.4", id="BX ENCODER read"),
        pytest.param("nextmove-bx", "ENCODER.5 = 10", id="BX ENCODER write"),
        pytest.param("nextmove-bx", "PRINT ENCODERVEL.7", id="BX ENCODERVEL"),
        pytest.param("nextmove-bx", "ENCODERSCALE.4 = 2", id="BX ENCODERSCALE"),
        pytest.param("nextmove-bx", "PRINT ENCODERWRAP.6", id="BX ENCODERWRAP"),
        pytest.param("nextmove-bx", "PRINT DAC.4", id="BX DAC"),
        pytest.param("nextmove-bx", "DACLIMITMAX.4 = 50", id="BX DACLIMITMAX"),
        pytest.param("nextmove-pci", "PRINT ENCODER.12", id="PCI past its encoders"),
        pytest.param("mintdrive", "PRINT ENCODER.1", id="MintDrive encoder 1"),
    ],
)
def test_a_channel_the_controller_lacks_is_error_4_in_check_and_run(controller: str, line: str) -> None:
    checked = [d.code for d in mintlang.check(line + "\n", controller=controller) if d.code.startswith("E")]
    assert checked == ["E0004"]
    result = simulate(f'{line}\nPRINT "after"\n' + HANDLER, controller=controller)
    assert result.terminal.startswith("ERR 4 ERL 1\n")


def test_the_channels_a_bx_has_and_its_other_axes_still_answer() -> None:
    # encoder 3 and DAC 3 exist; axis 5 is an axis, so POS.5 is no channel
    source = "PRINT ENCODER.3\nPRINT DAC.3\nPRINT POS.5\n"
    assert simulate(source, controller="nextmove-bx").terminal == "0\n0\n0\n"
