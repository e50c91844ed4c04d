"""X-GO-TIMING flags what a v3 GO delayed (001:3405-3412). A v3 OFFSET and a v3 CAM start without GO
(001:10402, 001:3893-3897); the GO v4 needs after them (000:14780, 000:3872) is the migration's, which
no v3 run waited at, so the statements after it ran as early in v3 as they do in v4."""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate


@pytest.mark.parametrize(
    "source",
    [
        # the v3 guide's offsets on a follow (001:3704-3709), each followed by a print
        'FOLLOW = 1\nOFFSET = 10\nPAUSE MODE = _follow\nOFFSET = -10\nPRINT "back"\n',
        "FOLLOW.0 = 1\nLOOP\n  OFFSET.0 = 5\n  OUT1 = 1\n  PAUSE MODE.0 = _follow\nENDL\n",
        # a one-shot cam run twice, the output set while the second runs
        "DIM cam0(3) = 2,10,-10\nCAM.0 = 0\nPAUSE CAMINDEX.0 = 2\nCAM.0 = 0\nOUT1 = 1\n",
    ],
)
def test_the_go_v4_needs_after_an_offset_or_a_cam_is_no_v3_wait(source: str) -> None:
    migrated = migrate(source)
    assert " : GO" in migrated.text  # the migration wrote the GOs
    assert [item.line for item in migrated.manual if item.rule == "X-GO-TIMING"] == []
