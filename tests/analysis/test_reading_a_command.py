"""Reading a keyword that is only a command is a syntax error, 2003, whatever the parser makes of it.

GO and AXES are both commands with no read attribute (AXES: "To define a default axis string",
Format AXES[axis list], 000:6883-6910); PRINT GO already said GO gives no value, while AXES, which the
grammar knows by its own token, was called a reserved word used as a variable. The commands the guide
prints no attribute table for are judged by their formats: TRON and CLS show only the bare command
(000:16922, 8264), so neither gives a value either. LASTERR's format is bare too, but its purpose is "to
return" the last error (000:13270-13282), so it reads (mintlang/keyworddb/supplements.py).
"""

from __future__ import annotations

import pytest

import mintlang


@pytest.mark.parametrize("command", ["GO", "AXES"])
def test_a_command_read_in_an_expression_gives_no_value(command: str) -> None:
    (diagnostic,) = mintlang.check(f"PRINT {command}\n")
    assert diagnostic.code == "E2003"
    assert f"{command} is a command and gives no value" in diagnostic.message


@pytest.mark.parametrize("command", ["TRON", "TROFF", "CLS", "BEEP", "VER"])
def test_a_command_without_an_attribute_table_gives_no_value(command: str) -> None:
    (diagnostic,) = mintlang.check(f"PRINT {command}\n")
    assert diagnostic.code == "E2003"
    assert f"{command} is a command and gives no value" in diagnostic.message


def test_a_keyword_after_goto_is_still_not_a_label() -> None:
    (diagnostic,) = mintlang.check("GOTO AXES\n")
    assert diagnostic.code == "E2006" and "as a label" in diagnostic.message
