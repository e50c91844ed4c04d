"""S-TERM: a v3 serial terminal written as _tmRS232 on a NextMove PCI, which has no RS232 port, is flagged.

v3 TERM = _serial sent the terminal to the serial port (001:12016-12020). v4 TERMINAL's table gives the
RS232 channel to NextMove BX and MintDrive, the dual port RAM to NextMove PC and PCI (000:16693-16697),
SERIALBAUD is not on the PC cards either (000:15817-15822), and a channel the controller lacks is ignored
(000:2028-2029): the migrated program printed to nowhere, silently.
"""

from __future__ import annotations

import pytest

from tests.migrate.helpers import one_rule

LACKS = (
    "NextMove PCI has no RS232 port and v4 ignores a channel the controller lacks (v4 guide section 3.9): "
    "its host terminal is the dual port RAM, _tmDPR (v4 guide section 10.3 TERMINAL)"
)


@pytest.mark.parametrize("source", ["TERM = _serial\n", "TM = 2\n"])
def test_a_serial_terminal_on_a_pci_card_is_flagged(source: str) -> None:
    result = one_rule("S-TERM", source)
    assert result.text.endswith("TERMINAL = _tmRS232\n")
    assert [item.reason for item in result.manual] == [LACKS]


def test_a_controller_with_the_port_gets_no_item() -> None:
    result = one_rule("S-TERM", "TERM = _serial\n", controller="nextmove-bx")
    assert (result.text, result.manual) == ("TERMINAL = _tmRS232\n", ())
