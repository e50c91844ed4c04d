"""A label after code on its line (``a = 1 : #lbl``) is not moved: it is left, flagged, for a person.

v4 takes a label only as the first thing on its line (000:1872-1876). The v3 guide writes every label that
way and gives one after code no meaning (001:2426-2461, 5418-5440), so which statement a GOTO to it would
land on, the line's first or the one after the code, is written nowhere, and the reader takes the line as
not valid Mint v3 either: moved above or below the code, the label would change what a jump to it runs.
The manual item names the label and says what is wrong.
"""

from __future__ import annotations

from mintlang.migrate import migrate

SOURCE = "a = 1 : #lbl\nPRINT a\nGOTO lbl\n"


def test_the_line_is_kept_as_written_and_flagged() -> None:
    result = migrate(SOURCE)
    kept = [line for line in result.text.splitlines() if not line.startswith(("REM MIGRATE:", "DIM "))]
    assert kept == SOURCE.splitlines()
    assert "not valid Mint v3 either (Syntax error: #lbl follows code: a label must begin its line)" in [
        item.reason for item in result.manual if item.line == 3
    ]


def test_its_jumps_keep_its_name_when_it_is_named_like_a_v4_event() -> None:
    # M-LABEL renames a label v4 would call as an event with its jumps (000:1884-1900); this one is defined
    # nowhere v3 reads, and the jump renamed alone named a label the user never wrote (#comms1_u)
    result = migrate("a = 1 : #comms1\nGOTO comms1\n", only=["M-LABEL", "X-COMMENTED"])
    assert "GOTO comms1\n" in result.text
    assert "label #comms1 is not in this file" in [item.reason for item in result.manual]
