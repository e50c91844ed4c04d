"""A v3 error handler that prints ERR shows another number after migration, so X-ERR flags it.

The v3 guide numbers ERR 0 to 15, a following error 11 (001:4918-4937), and its own handler prints
the number (001:5059: ``PRINT "Error ", ERR, "reported"``). v4 reports every motion error as ERR 500
(000:18893). The migrated handler prints 500 where v3 printed 11: a difference the migration must
name, as it names a comparison of ERR with a number.
"""

from __future__ import annotations

from mintlang.migrate import migrate
from mintlang.migrate.verification import Place, Verdict, verify

# Axis 1 cannot move, so its following error passes MFOLERR = 50 counts early in the move.
HANDLER = """REM @sim plant 1 stalled
RESET[0,1,2]
MFOLERR = 50;
MOVER = 100,100 : GO
PAUSE IDLE[0,1]
END
#ONERROR
  PRINT "Error ", ERR, "reported"
  CANCEL[0,1]
RETURN
"""


def test_the_printed_number_is_a_manual_item() -> None:
    result = migrate(HANDLER)
    assert [item.original_line for item in result.manual if item.rule == "X-ERR"] == [8]


def test_verify_finds_the_difference_on_the_flagged_line() -> None:
    result = migrate(HANDLER)
    found = verify(result, until_ms=200)
    assert found.verdict is Verdict.DIVERGES and found.divergence is not None
    assert (found.divergence.v3, found.divergence.v3_line) == ("'11reported'", Place("program", 8))
    assert 8 in {item.original_line for item in result.manual if item.rule == "X-ERR"}
