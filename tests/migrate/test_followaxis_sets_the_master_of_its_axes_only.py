"""S-MASTER writes MASTERSOURCE for the axes FOLLOWAXIS set, no more.

A v3 write without brackets gives its values to the first axes of the AXES default, one each, and a
skipped place leaves its axis as it was (001:1029-1066, v3's default string is 0,1,2). v4 MASTERSOURCE
takes the same places, a ';' filling every axis of the list (000:629-658), and writing it sets that axis'
MASTERCHANNEL back to its default (000:13947): a ';' the v3 line did not have changed the master of
axes FOLLOWAXIS left alone, such as axis 1 following the SPEED demand below.
"""

from __future__ import annotations

import pytest

from tests.migrate.helpers import rewritten


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        (
            "AXES[0,1]\nFOLLOWAXIS.1 = -1\nFOLLOWAXIS = 1\n",
            "AXES[0,1]\nMASTERSOURCE.1 = _msSPEED\nMASTERSOURCE = _msPOS : MASTERCHANNEL = 1\n",
        ),
        ("FOLLOWAXIS = -1\n", "MASTERSOURCE = _msSPEED\n"),  # axis 0 of 0,1,2
        ("FOLLOWAXIS = ,2\n", "MASTERSOURCE = , _msPOS : MASTERCHANNEL = ,2\n"),  # axis 1 only
        ("FOLLOWAXIS[0,1] = 2\n", "MASTERSOURCE[0,1] = _msPOS : MASTERCHANNEL[0,1] = 2\n"),
        # every axis named gets a value, or the ';' fills them: the ';' says the same
        ("FOLLOWAXIS[0,1] = 2;\n", "MASTERSOURCE[0,1] = _msPOS; : MASTERCHANNEL[0,1] = 2;\n"),
        ("AXES[0,1]\nFOLLOWAXIS = 2,2\n", "AXES[0,1]\nMASTERSOURCE = _msPOS; : MASTERCHANNEL = 2,2\n"),
    ],
)
def test_master_source_goes_to_the_axes_followaxis_set(source: str, expected: str) -> None:
    assert rewritten("S-MASTER", source) == expected
