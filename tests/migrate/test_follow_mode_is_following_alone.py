"""v3 MODE = _follow (9) is following and nothing else: v3 MODE holds one mode, 8 while an OFFSET runs on
the follow and 15 during a clutch (001:10038-10058, 001:3736), so the v3 guide waits for an offset to end
with PAUSE MODE = _follow (001:3704-3709). v4 AXISMODE keeps the FOLLOW bit through both, adding OFFSET or
FLY (000:7119-7120, 000:14791-14793): only AXISMODE = _mdFOLLOW says what MODE = 9 said, as for mode 18."""

from __future__ import annotations

import pytest

from tests.migrate.helpers import rewritten


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        # the v3 guide's wait for an offset on a follow (001:3704-3709)
        ("OFFSET = 10\nPAUSE MODE = _follow\n", "OFFSET = 10\nPAUSE AXISMODE = _mdFOLLOW\n"),
        ("IF MODE.1 = 9 THEN x = 1\n", "IF AXISMODE.1 = _mdFOLLOW THEN x = 1\n"),
        ("IF MODE.1 <> _follow THEN x = 1\n", "IF AXISMODE.1 <> _mdFOLLOW THEN x = 1\n"),
        ("x = MODE = _follow\n", "x = AXISMODE = _mdFOLLOW\n"),
    ],
)
def test_mode_follow_is_the_follow_bit_alone(source: str, expected: str) -> None:
    assert rewritten("S-MODE", source) == expected
