"""A keyword the simulated controller lacks stops the run with error 17, naming the controllers that have it.

Error 17 is "Keyword not supported on this platform" (000:18570-18575); SERIALBAUD is a keyword of NextMove BX,
MintDrive and ServoNode 51 only (its Controllers Supported row, 000:15817-15823). ``mint check`` names them
(tests/analysis/test_a_keyword_the_controller_lacks_names_those_that_have_it.py); the run's stop line says the
same, so a newcomer running the guide's example on the default NextMove PCI learns which controller to simulate.
"""

from __future__ import annotations

from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate


def test_the_stop_names_the_simulated_controller_and_those_with_the_keyword() -> None:
    result = simulate("SERIALBAUD._tmRS232 = 9600\n", controller="nextmove-pci", enable=False)
    assert result.stop.reason is StopReason.ERROR
    assert int(result.err) == 17
    assert (
        "(SERIALBAUD is not available on NextMove PCI, only on NextMove BX, MintDrive and ServoNode 51)"
        in result.stop.message
    )
