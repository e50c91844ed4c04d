"""S-CHAN: ``ENCODER`` read without axes becomes a read of the first default axis's channel.

A v3 read without axes reads the first axis of the AXES default (``a = POS`` is ``a = POS[0]``
after ``AXES[0,1]``, 001:1063-1071; ``PAUSE IDLE`` waits for the first one only, 001:1123-1129).
v4 channel keywords take one channel in dot syntax (000:548-561), so with the default known the
read is written out; with a computed AXES it is not known and stays a manual item.
"""

from __future__ import annotations

import pytest

from tests.migrate.helpers import flagged, rewritten


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("AXES[1,2]\nb = ENCODER\n", "AXES[1,2]\nb = ENCODER.1\n"),
        ("AXES[2]\nPRINT FC\n", "AXES[2]\nPRINT FASTENCODER.2\n"),
        ("b = EN + 1\n", "b = ENCODER.0 + 1\n"),  # the power-up default AXES[0,1,2] (001:1029-1033)
    ],
    ids=["after AXES", "abbreviated", "power-up default"],
)
def test_the_read_names_the_first_default_axis(source: str, expected: str) -> None:
    assert rewritten("S-CHAN", source) == expected


def test_a_computed_default_is_left_for_a_person() -> None:
    assert flagged("S-CHAN", "AXES[a]\nb = ENCODER\n") == ["ENCODER reads one channel: write ENCODER.<channel>"]


def test_a_read_of_several_axes_is_left_for_a_person() -> None:
    # several axes read are ANDed bitwise (001:1131): no one channel gives that
    assert flagged("S-CHAN", "b = ENCODER[0,1]\n") == ["ENCODER reads one channel: write ENCODER.<channel>"]
