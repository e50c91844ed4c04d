"""CONFIG takes on each NextMove only the motor types its table ticks for that controller, in mint check and mint-run.

CONFIG's table of motor types ticks a controller for each value (000:8431-8443): _cfOFF on NextMove PCI, PC and
BX (and MintDrive), _cfSERVO on all five, _cfSTEPPER on NextMove PCI and PC, _cfPWM on one (the quick reference
gives PWMONTIME and PWMPERIOD to NextMove PC alone, 000:17742-17744), _cfVIRTUAL on the three NextMoves, and 4,
"Reserved", on none. "The value that an axis will accept depends on the physical channels available"
(000:8444-8445): NextMove BX has no stepper pulse and direction outputs (0 in the I/O table, where NextMove PC has
4x3 and NextMove PCI 4x2: 000:4050-4052). The attributes row prints "0 - 5" for the NextMoves together
(000:8420), as MintDrive's "0 ≤ x ≤1, 6" and ServoNode 51's "1" follow their ticks. A value the controller does
not accept is #3, "Data specified out of range" (000:18518-18521), at its line when it runs.
"""

from __future__ import annotations

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from tests.analysis.checking import ERROR, found
from tests.runtime.running import simulate

_REFUSED = [
    ("nextmove-bx", "_cfSTEPPER"),
    ("nextmove-bx", "_cfPWM"),
    ("nextmove-bx", "4"),
    ("nextmove-pci", "_cfPWM"),
    ("nextmove-pci", "4"),
    ("nextmove-pc", "4"),
]
_TAKEN = [
    ("nextmove-bx", "_cfOFF"),
    ("nextmove-bx", "_cfSERVO"),
    ("nextmove-bx", "_cfVIRTUAL"),
    ("nextmove-pci", "_cfSTEPPER"),
    ("nextmove-pci", "_cfVIRTUAL"),
    ("nextmove-pc", "_cfSTEPPER"),
    ("nextmove-pc", "_cfPWM"),
    ("nextmove-pc", "_cfVIRTUAL"),
]


@pytest.mark.parametrize(("controller", "value"), _REFUSED)
def test_a_motor_type_the_controller_lacks_is_error_3(controller: str, value: str) -> None:
    assert found(f"CONFIG.0 = {value}\n", controller=controller) == [("E0003", ERROR, 1)]
    result = simulate(f'PRINT "before"\nCONFIG.0 = {value}\n', controller=controller, enable=False)
    assert result.stop.reason is StopReason.ERROR
    assert (result.err, result.erl) == (3, 2)
    assert result.terminal.startswith("before\n")


@pytest.mark.parametrize(("controller", "value"), _TAKEN)
def test_a_motor_type_the_controller_has_is_taken(controller: str, value: str) -> None:
    assert found(f"CONFIG.0 = {value}\n", controller=controller) == []
