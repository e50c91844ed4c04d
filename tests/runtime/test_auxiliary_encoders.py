"""AUXENCODER: the channels each controller has and the values the keyword takes (000:6693-6733)."""

from __future__ import annotations

import pytest

from tests.runtime.running import simulate


def test_an_auxiliary_encoder_reads_what_was_written_to_it() -> None:
    # 000:6717: AUXENCODER sets the position; nothing turns the encoder in the simulation
    source = 'PRINT AUXENCODER.0\nAUXENCODER.2 = -8388607\nPRINT AUXENCODER.2, " ", AUXENCODER.0\n'
    assert simulate(source, controller="nextmove-pci").terminal == "0\n-8388607 0\n"


@pytest.mark.parametrize("value", ["8388608", "-8388608"])
def test_a_value_outside_the_table_is_error_3(value: str) -> None:
    # 000:6714-6715: -8388607.0 to 8388607.0 on every controller
    result = simulate(f"AUXENCODER.0 = 12\nAUXENCODER.0 = {value}\nPRINT AUXENCODER.0\n", controller="nextmove-pci")
    assert (result.err, result.erl, result.terminal.splitlines()[0]) == (
        3,
        2,
        "R0003: PROGRAM Data specified out of range [axis/channel 0] [line 2]",
    )
    assert "it takes -8388607 to 8388607" in result.stop.message


@pytest.mark.parametrize(("controller", "missing"), [("nextmove-pci", 3), ("nextmove-bx", 1), ("mintdrive", 1)])
def test_a_channel_the_controller_lacks_is_error_4(controller: str, missing: int) -> None:
    # 000:5626-5628, 18522-18524: NextMove PCI has auxiliary encoders 0 to 2, BX and MintDrive 0 alone
    result = simulate(f"AUXENCODER.{missing} = 1\n", controller=controller)
    assert (result.err, result.erl) == (4, 1)
