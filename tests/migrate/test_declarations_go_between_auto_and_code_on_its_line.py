"""What the migration inserts at the top of a configuration file (DIM, AXES) goes right after its
AUTO, also when AUTO shares its line with code: v3 only asks for AUTO to be the first command
(v3:5838), so ``AUTO : SP = 10 : a = 1`` is a v3 configuration file. v4 wants AUTO first, REM
lines included (v4:6647), and every variable DIMmed before it is used (v4:897-910, #3001
v4:19073). The insertions went below the whole line, so ``DIM a`` came after ``a = 1``: the
migrated file did not compile and mint-migrate flagged its own output (X-CHECK E3001). The line is
now broken after AUTO (a line end separates statements as ``:`` does, v4:5674-5692) and the
insertions go in between."""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate


@pytest.mark.parametrize(
    ("config", "migrated"),
    [
        pytest.param("AUTO : a = 1\n", "AUTO\nDIM a\na = 1\n", id="a-variable"),
        pytest.param("AUTO : a = 1 : REM set up\n", "AUTO\nDIM a\na = 1 : REM set up\n", id="before-a-comment"),
        pytest.param("AUTO : REM set up\na = 1\n", "AUTO : REM set up\nDIM a\na = 1\n", id="only-a-comment"),
        pytest.param("AUTO\r\nOUT1 = 1 : a = 1\r\n", "AUTO\r\nDIM a\r\nOUT1 = 1 : a = 1\r\n", id="alone-crlf"),
    ],
)
def test_a_declaration_goes_right_after_auto(config: str, migrated: str) -> None:
    result = migrate("END\n", config=config, controller="mintdrive", only=["M-DIM"])
    assert result.configuration is not None
    assert result.configuration.text == migrated


def test_the_whole_migration_of_code_after_auto_compiles() -> None:
    result = migrate("? a\n", config="AUTO : SP = 10 : a = 1\n", controller="mintdrive")
    assert result.configuration is not None
    assert result.configuration.text.startswith("AUTO\n")
    assert "DIM a\n" in result.configuration.text
    assert result.configuration.text.index("DIM a\n") < result.configuration.text.index("a = 1")
    assert [item.rule for item in result.configuration.manual if not item.note] == []
