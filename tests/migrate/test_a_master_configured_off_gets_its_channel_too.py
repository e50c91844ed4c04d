"""S-MASTER: where an axis is configured off, the manual item gives both statements that follow its encoder.

v4 follows an axis that is off by its encoder, MASTERSOURCE = _msENCODER, and changing MASTERSOURCE sets
MASTERCHANNEL back to its default (000:13936-13947); the v4 guide's cam follows axis 2's encoder with
MASTERSOURCE = _msENCODER and MASTERCHANNEL = 2 (000:3910-3911). Advice naming MASTERSOURCE alone left
the follower on the default channel, not on the axis FOLLOWAXIS named (001:3690-3696).
"""

from __future__ import annotations

import pytest

from tests.migrate.helpers import flagged


@pytest.mark.parametrize(
    ("source", "statements"),
    [
        ("CONFIG.1 = _off\nFOLLOWAXIS.0 = 1\n", "MASTERSOURCE.0 = _msENCODER : MASTERCHANNEL.0 = 1"),
        ("CONFIG.2 = 0\nfollowaxis[0,1] = 2,2\n", "mastersource[0,1] = _msENCODER; : masterchannel[0,1] = 2,2"),
    ],
)
def test_an_axis_configured_off_gets_source_and_channel(source: str, statements: str) -> None:
    assert flagged("S-MASTER", source) == [
        f"an axis is configured off: if it is the master, write {statements} (in this order: MASTERSOURCE "
        "resets MASTERCHANNEL)"
    ]
