"""A v3 DEFAULT is left for a person: v4's also unassigns the inputs the v3 hardware had and sets v4's values.

The v3 guide: DEFAULT returns the motion variables to their power-up values (001:7247-7251), and the
limit, home, stop and error inputs and the amplifier enable are the controller's own (001:4600,
5011-5018, 11411), so they stay. The v4 guide's DEFAULT sets DRIVEENABLEOUTPUT, ERRORINPUT,
HOMEINPUT, LIMITFORWARDINPUT, LIMITREVERSEINPUT and STOPINPUT to -1, none, and FOLERRORFATAL,
IDLEPOS and SPEED to 1000, 1000 and 20000 (000:9004-9059), where v3's power-up values are 16000,
16000 and 40000 (001:9989, 8741, 11797). After a migrated DEFAULT the axis runs without the limit
switches the prologue assigned, and at v4's speed. v3 DEFAULT also reset what RESET resets, the guide
telling the two apart only by the parameters RESET leaves (001:7244-7251): the outputs cleared, TIME 0
and IMASK 255 (001:11438-11442), which v4 DEFAULT does not list (000:9004-9059).
"""

from __future__ import annotations

from mintlang.migrate import migrate
from tests.migrate.helpers import flagged

REASON = (
    "DEFAULT: v4 DEFAULT unassigns the limit, home, stop, error inputs and drive enable output, sets v4's values "
    "(FOLERRORFATAL 1000, IDLEPOS 1000, SPEED 20000), keeps OUT, TIME, IMASK (v3 cleared them): redo them after it"
)


def test_default_is_a_manual_item() -> None:
    assert flagged("X-DEFAULT", "DEFAULT\nDEFAULT[0,1] : REM start afresh\n") == [REASON, REASON]


def test_the_guides_example_is_flagged_in_a_whole_migration() -> None:
    result = migrate("DEFAULT[0]\nMOVER.0 = 100 : GO.0\n")  # 001:7253
    assert [item.original_line for item in result.manual if item.rule == "X-DEFAULT"] == [1]
