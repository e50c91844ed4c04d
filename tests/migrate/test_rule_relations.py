"""M-RELATION: a relation the v3 guide writes with blanks inside becomes one piece for v4.

The v3 guide runs ``PAUSE DEMAND > = 50`` (v3:3096); the v4 guide prints its relations in one
piece only (``>=``, ``<=``, ``<>``: v4:1262-1264), and a v4 compiler reads ``> =`` as two tokens.
"""

from __future__ import annotations

import pytest

import mintlang
from tests.migrate.helpers import rewritten


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("PAUSE DEMAND > = 50\n", "PAUSE DEMAND >= 50\n"),
        ("IF a <  = b THEN PRINT a\n", "IF a <= b THEN PRINT a\n"),
        ("WHILE a < > 3 : a = a + 1 : ENDW\n", "WHILE a <> 3 : a = a + 1 : ENDW\n"),
        (
            "PRINT a > = 1, a < > 2 : REM a > = 1 stays in the comment\n",
            "PRINT a >= 1, a <> 2 : REM a > = 1 stays in the comment\n",
        ),
    ],
)
def test_a_spaced_relation_is_written_in_one_piece(source: str, expected: str) -> None:
    assert rewritten("M-RELATION", source) == expected


@pytest.mark.parametrize(
    "source",
    ["PAUSE a >= 50\n", "PAUSE a > 50\n", 'PRINT "a > = b"\n', "IF a < -1 THEN GO\n"],
)
def test_a_relation_in_one_piece_and_text_in_strings_stay(source: str) -> None:
    assert rewritten("M-RELATION", source) == source


def test_the_result_reads_as_v4() -> None:
    text = rewritten("M-RELATION", "a = 3\nIF a > = 2 THEN PRINT a\n")
    assert [d.code for d in mintlang.parse(text, "v4").diagnostics] == []
