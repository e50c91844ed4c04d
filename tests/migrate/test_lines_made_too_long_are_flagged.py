"""A line the migration makes longer than the controller takes is flagged (spec §1 step 8).

The v4 guide's command line takes up to 255 characters a line (its "Introduction" to the
command line), which ``mint check`` reports as W111. Rewrites lengthen lines: each v3 ``SIN(1)``
becomes ``(SIN(1) * 1000)``, nine characters more (v3 SIN is 1000 times the sine, v4's is the sine).
X-CHECK puts a marker above such a line; the line itself is kept as the rules wrote it.
"""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate


def _sines(count: int) -> str:
    return "x = " + " + ".join(["SIN(1)"] * count)  # 4 + 6 * count + 3 * (count - 1) characters


@pytest.mark.parametrize("newline", ["\n", "\r\n", "\r"], ids=["LF", "CR LF", "CR"])
def test_a_line_pushed_past_255_characters_gets_a_marker(newline: str) -> None:
    line = _sines(25)  # 226 characters in v3, 226 + 25 * 9 = 451 in v4
    result = migrate(newline.join(["DIM a(2)", "PRINT 1", line, line, "PRINT x", ""]))
    assert [(item.rule, item.original_line) for item in result.manual] == [("X-CHECK", 3), ("X-CHECK", 4)]
    assert "line of 451 characters: NextMove PCI takes 255" in result.manual[0].reason


def test_a_line_of_255_characters_is_not_flagged() -> None:
    line = _sines(11) + " " * (255 - (4 + 66 + 30 + 11 * 9))  # exactly 255 characters once migrated
    result = migrate(f"DIM a(2)\n{line}\nPRINT x\n")
    assert [item.rule for item in result.manual] == []
    assert max(len(text) for text in result.text.splitlines()) == 255


def test_the_migrated_file_is_not_flagged_again() -> None:
    result = migrate(f"DIM a(2)\n{_sines(25)}\nPRINT x\n")
    again = migrate(result.text)
    assert again.text == result.text and not again.changes
