"""``mint check`` holds MOVEOUT's bank and pattern and CONTOURPARAMETER's angle to what the run holds them to.

The notes print no range for either (004:223-232, 288-297). CONTOURPARAMETER's index 0 is the inter-vector
angle v4 calls CONTOURANGLE, 0 to 180 (000:8528, MT-11). MOVEOUT's bank is a card: 0 to 2 on a NextMove
PCI, BANK's range (000:7329), the only controller with expansion cards, so bank 0 alone on a NextMove BX
(000:7320-7321); its pattern sets the bank's outputs, one bit each, 12 a PCI card (000:7340-7342) and 8 on
a BX (000:14943), so below 4096 or 256, a whole number (MT-22). Outside, both tools give error 3.
"""

from __future__ import annotations

import pytest

from mintlang.runtime.run import Limits, run_source
from mintlang.runtime.scenario import DrivesEnabled, Scenario
from tests.analysis.placed import placed

_ENABLED = Scenario(drives=(DrivesEnabled(),))
_BUFFER = "MOVEBUFFERSIZE(0) = 4\n"


@pytest.mark.parametrize(
    ("controller", "line", "at"),
    [
        pytest.param("nextmove-pci", "MOVEOUT(0,3) = 5", "3", id="PCI bank 3"),
        pytest.param("nextmove-bx", "MOVEOUT(0,1) = 5", "1", id="BX bank 1"),
        pytest.param("nextmove-pci", "MOVEOUT(0,0) = 4096", "4096", id="PCI pattern 4096"),
        pytest.param("nextmove-bx", "MOVEOUT(0,0) = 256", "256", id="BX pattern 256"),
        pytest.param("nextmove-pci", "MOVEOUT(0,1) = 2.5", "2.5", id="a fraction of a pattern"),
        pytest.param("nextmove-pci", "CONTOURPARAMETER([0,1],0) = 181", "181", id="angle 181"),
        pytest.param("nextmove-bx", "CONTOURPARAMETER(0,0) = -1", "-1", id="angle -1"),
    ],
)
def test_a_value_the_run_refuses_is_error_3_in_the_check(controller: str, line: str, at: str) -> None:
    source = _BUFFER + line + "\n"
    assert placed(source, "code", "text", codes="E", dialect="mintmt", controller=controller) == [("E0003", at)]
    limits = Limits(until_ms=1000, max_wall_s=60.0)
    result = run_source(source, dialect="mintmt", controller=controller, scenario=_ENABLED, limits=limits)
    assert (result.err, result.erl) == (3, 2)


@pytest.mark.parametrize(
    ("controller", "line"),
    [
        pytest.param("nextmove-pci", "MOVEOUT(0,2) = 4095", id="PCI's last card, every output"),
        pytest.param("nextmove-bx", "MOVEOUT(0,0) = 255", id="BX's outputs"),
        pytest.param("nextmove-pci", "CONTOURPARAMETER([0,1],0) = 10", id="the note's 10 degrees"),
        pytest.param("nextmove-pci", "CONTOURPARAMETER([0,1],0) = 180", id="180 degrees"),
    ],
)
def test_a_value_in_range_is_clean(controller: str, line: str) -> None:
    source = _BUFFER + line + "\n"
    assert placed(source, "code", "text", codes="E", dialect="mintmt", controller=controller) == []
