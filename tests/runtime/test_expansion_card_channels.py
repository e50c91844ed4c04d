"""The NextMove PCI's expansion-card channels: the checker accepts them, the simulation fits no card.

A NextMove PCI reads inputs 0 to 19 and drives outputs 0 to 11 from its main card; expansion
cards add inputs 20 to 59 and outputs 12 to 35 (000:4076-4078, 4125-4127). ``mint-run``
simulates the main card alone (``runtime/BEHAVIOUR.md``), so a program using a card's channel
stops with the controller's error 7 or 8, and the message says the channel is on a card rather
than leave a program ``mint check`` accepted looking wrong.
"""

from __future__ import annotations

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate


@pytest.mark.parametrize(
    ("statement", "code", "detail"),
    [
        pytest.param("PRINT IN.21", "R0007", "channels are 0 to 19; 20 to 59 are on expansion cards", id="input"),
        pytest.param("OUT.14 = 1", "R0008", "channels are 0 to 11; 12 to 35 are on expansion cards", id="output"),
    ],
)
def test_a_channel_of_an_expansion_card_stops_the_run_and_says_so(statement: str, code: str, detail: str) -> None:
    result = simulate(statement + "\n", controller="nextmove-pci")
    assert result.stop.reason is StopReason.ERROR
    assert code in result.stop.message and detail in result.stop.message


@pytest.mark.parametrize("statement", ["PRINT IN.60", "OUT.36 = 1"])
def test_a_channel_beyond_every_card_is_not_said_to_be_on_one(statement: str) -> None:
    result = simulate(statement + "\n", controller="nextmove-pci")
    assert result.stop.reason is StopReason.ERROR
    assert "expansion" not in result.stop.message
