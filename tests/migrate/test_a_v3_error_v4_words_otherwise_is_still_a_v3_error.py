"""X-COMMENTED: a line already an error in v3 is reported as such, whatever v4's checker calls the error.

v3 VER is a command that prints the version and gives no value (001:12496-12504), so PRINT "ver ";VER was
already an error in v3; v4 rejects it at the same word with a message of its own. The README promises the
X-COMMENTED marker for such a line; it got X-CHECK's 'not valid Mint v4', as if the migration had broken it.
"""

from __future__ import annotations

from mintlang.migrate import migrate


def test_a_line_v3_rejects_is_marked_as_invalid_in_v3() -> None:
    result = migrate('PRINT "ver ";VER\nPRINT "ok"\n')
    assert [item.rule for item in result.manual] == ["X-COMMENTED"]
    assert result.manual[0].reason == (
        "not valid Mint v3 either (Read only or Command: VER is a command in Mint v3 and gives no value)"
    )
    assert migrate(result.text).text == result.text
