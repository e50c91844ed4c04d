"""TIME counts milliseconds up to the top of the range its table gives, then starts again at 0.

NextMove's TIME goes up every millisecond to at most 16777215 (000:16753-16754); MintDrive's
table gives 0 ≤ x ≤ 65535 (000:16747), so its TIME never reads more than 65535 either. Writing
TIME sets the count (000:16751-16752): 65535 then 3 ms is 65538 on NextMove, 2 on MintDrive.
"""

from __future__ import annotations

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate


@pytest.mark.parametrize(("controller", "reading"), [("nextmove-pci", "65538"), ("mintdrive", "2")])
def test_time_past_65535(controller: str, reading: str) -> None:
    result = simulate("TIME = 65535\nWAIT = 3\nPRINT TIME\n", controller=controller)
    assert (result.stop.reason, result.terminal) == (StopReason.END, f"{reading}\n")


def test_time_on_nextmove_wraps_after_16777215() -> None:
    result = simulate("TIME = 16777215\nWAIT = 2\nPRINT TIME\n", controller="nextmove-pci")
    assert (result.stop.reason, result.terminal) == (StopReason.END, "1\n")
