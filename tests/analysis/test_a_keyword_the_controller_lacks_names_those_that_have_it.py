"""Error 17 on a keyword the controller lacks names the controllers whose "Controllers Supported" row ticks it.

Each entry ticks the controllers it runs on, in the order NextMove PCI, NextMove PC, NextMove BX, MintDrive,
ServoNode 51 (000:5678-5681); #17 is "Keyword not supported on this platform" (000:18570). Someone moving a
program between controllers learns from the message where the keyword is to be had, not only that it is not
here.
"""

from __future__ import annotations

import pytest

import mintlang


@pytest.mark.parametrize(
    ("source", "controller", "detail"),
    [
        # 000:15457: RELAY ticks the three NextMove controllers
        pytest.param(
            "RELAY.0 = 1\n",
            "mintdrive",
            "RELAY is not available on MintDrive, only on NextMove PCI, NextMove PC and NextMove BX",
            id="relay",
        ),
        # 000:12970: KIRFF ticks ServoNode 51 alone
        pytest.param(
            "KIRFF = 1\n", "mintdrive", "KIRFF is not available on MintDrive, only on ServoNode 51", id="kirff"
        ),
        # 000:16240: SPEEDDEMAND ticks MintDrive and ServoNode 51
        pytest.param(
            "SPEEDDEMAND = 10\n",
            "nextmove-bx",
            "SPEEDDEMAND is not available on NextMove BX, only on MintDrive and ServoNode 51",
            id="speeddemand",
        ),
        # 000:7323: BANK ticks NextMove PCI alone
        pytest.param(
            "BANK = 1\n", "nextmove-pc", "BANK is not available on NextMove PC, only on NextMove PCI", id="bank"
        ),
    ],
)
def test_error_17_names_the_controllers_that_have_the_keyword(source: str, controller: str, detail: str) -> None:
    (diagnostic,) = mintlang.check(source, controller=controller)
    assert (diagnostic.code, diagnostic.message) == ("E0017", f"Keyword not supported on this platform: {detail}")
