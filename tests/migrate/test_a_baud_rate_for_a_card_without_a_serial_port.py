"""S-BAUD: on a controller with no serial port the item says there is no port to set a rate for.

SERIALBAUD, which sets the rate of v4's serial ports, is not on the NextMove PCI and PC cards
(000:15817-15822), whose host terminal is the dual port RAM (000:16693-16697). The item said only that
SERIALBAUD is not available, leaving v3's BAUD = 9600 (001:6092-6124) for a person to rewrite as something.
"""

from __future__ import annotations

from tests.migrate.helpers import flagged


def test_a_baud_rate_on_a_pci_card_is_to_be_removed() -> None:
    assert flagged("S-BAUD", "BAUD = 9600\n") == [
        "NextMove PCI has no serial port (SERIALBAUD is not on it): remove the BAUD; "
        "its host terminal is the dual port RAM, _tmDPR (v4 guide section 10.3 TERMINAL)"
    ]
