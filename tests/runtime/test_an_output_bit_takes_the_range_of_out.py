"""``OUT.x = v`` is held to OUT's range, in ``mint-run`` as in ``mint check``.

OUT's attributes table gives one range for the keyword, whichever of its formats writes it (``OUT =``,
``OUT.x =``, ``OUTx =``, 000:14887-14895): 0 ≤ x < 4096 on NextMove PCI, 0 ≤ x < 256 on NextMove BX
(000:14908-14913). A value outside it is error 3 (000:18518-18521), which ``#ONERROR`` sees, and the output
keeps its state; a value inside it sets the output when it is not 0 (``OUT.2 = 1``, 000:14926-14927).
"""

from __future__ import annotations

import pytest

from mintlang.runtime.run import run_source
from tests.analysis.placed import placed

HANDLER = 'PRINT OUT\nEND\n#ONERROR\nPRINT ERR, " ",\nRETURN\n'


@pytest.mark.parametrize(
    ("controller", "line", "printed"),
    [
        pytest.param("nextmove-pci", "OUT.2 = 4096", "3 0", id="PCI-past-the-top"),
        pytest.param("nextmove-pci", "OUT2 = -1", "3 0", id="PCI-below-0"),
        pytest.param("nextmove-bx", "OUT.2 = 256", "3 0", id="BX-past-the-top"),
        pytest.param("nextmove-pci", "OUT.2 = 4095", "4", id="PCI-the-top-is-in-range"),
        pytest.param("nextmove-bx", "OUT.2 = 1", "4", id="BX-one"),
    ],
)
def test_an_output_bit_takes_the_range_of_out(controller: str, line: str, printed: str) -> None:
    refused = printed.startswith("3 ")
    assert placed(f"{line}\n", "code", controller=controller, codes="E") == ([("E0003",)] if refused else [])
    result = run_source(f"{line}\n{HANDLER}", controller=controller)
    assert result.terminal == printed + "\n"
