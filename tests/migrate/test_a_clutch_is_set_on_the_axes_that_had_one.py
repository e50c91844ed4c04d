"""S-CLUTCH sets FOLLOWMODE = _fmCLUTCH on the axes whose v3 FOLLOW ramped over a MASTERINC, no others.

v3 FOLLOW locks onto the master at once (001:3700); a MASTERINC on the axis gives it a clutch distance
(001:3716-3738). A ';' copied from the FOLLOW's selector set the clutch on every axis the list or the
default names, so a later FOLLOW.1 without MASTERINC ramped in v4 (000:3529-3535), and an axis already
following refused the write (000:3546).
"""

from __future__ import annotations

import pytest

from tests.migrate.helpers import rewritten


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        (
            "AXES[0,1]\nMASTERINC.0 = 100\nFOLLOW = 1\nFOLLOW.1 = 2\n",
            "AXES[0,1]\nMASTERINC.0 = 100\nFOLLOWMODE.0 = _fmCLUTCH : FOLLOW = 1\nFOLLOW.1 = 2\n",
        ),
        (
            "MASTERINC.0 = 100\nFOLLOW[0,1] = 1,1\n",
            "MASTERINC.0 = 100\nFOLLOWMODE.0 = _fmCLUTCH : FOLLOW[0,1] = 1,1\n",
        ),
        (
            "MASTERINC[0,1] = 100,200\nfollow[0,1] = 1,1\n",
            "MASTERINC[0,1] = 100,200\nfollowmode[0,1] = _fmCLUTCH; : follow[0,1] = 1,1\n",
        ),
    ],
)
def test_the_clutch_goes_to_the_axes_with_a_master_increment(source: str, expected: str) -> None:
    assert rewritten("S-CLUTCH", source) == expected
