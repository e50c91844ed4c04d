"""MASTERSOURCE and MASTERCHANNEL take each controller's own power-up value and range (000:13777-13970)."""

from __future__ import annotations

import pytest

from tests.runtime.running import simulate


@pytest.mark.parametrize(
    ("controller", "source"), [("nextmove-pci", "0"), ("nextmove-bx", "0"), ("mintdrive", "2"), ("servonode51", "2")]
)
def test_the_master_source_at_power_up_is_the_controllers_default(controller: str, source: str) -> None:
    # 000:13925-13929: NextMove defaults to _msPOS (0), MintDrive and ServoNode 51 to _msAUXENCODER (2)
    assert simulate("PRINT MASTERSOURCE.0\n", controller=controller).terminal == f"{source}\n"


@pytest.mark.parametrize(
    ("controller", "channel", "accepted"), [("mintdrive", 1, "0"), ("nextmove-pci", 12, "whole numbers: 0 to 11")]
)
def test_a_master_channel_outside_the_controllers_range_is_error_3(
    controller: str, channel: int, accepted: str
) -> None:
    # 000:13799-13803: NextMove takes channels 0 to 11, MintDrive and ServoNode 51 channel 0 alone; a channel
    # is a whole number (supplements.whole_only)
    result = simulate(f"MASTERCHANNEL.0 = {channel}\n", controller=controller)
    assert (result.err, result.erl) == (3, 1)
    assert result.stop.message.endswith(f"(MASTERCHANNEL = {channel}; it takes {accepted}) [line 1]")


def test_mintdrive_follows_its_auxiliary_encoder_by_default() -> None:
    # 000:13925-13929, 6719-6720: the master is the auxiliary encoder, which moves only when the program sets it;
    # at ratio 2 the slave moves twice what the master does (FG-1); AXISMODE bit 7 is _mdFOLLOW (000:7155)
    source = 'FOLLOW.0 = 2\nWAIT = 10\nPRINT POS.0, " ", AXISMODE.0\nAUXENCODER.0 = 100\nWAIT = 10\nPRINT POS.0\n'
    assert simulate(source, controller="mintdrive").terminal == "0 128\n200\n"


def test_an_auxiliary_encoder_the_controller_lacks_is_error_4_when_the_move_loads() -> None:
    # 000:5626-5628: NextMove BX has auxiliary encoder 0 alone
    result = simulate("MASTERSOURCE.1 = _msAUXENCODER : MASTERCHANNEL.1 = 1\nFOLLOW.1 = 1\n", controller="nextmove-bx")
    assert (result.err, result.erl) == (4, 2)
