"""A block closer the compiler cannot match is marked at its word, not at what follows it.

The guide's errors 2009 and 2013 are about the word itself: ``NEXT`` or ``UNTIL`` met while another block
is open on top of the stack (000:18954-18964, 19011-19019). An ``UNTIL``'s condition, or a loop variable
written after ``NEXT``, is not what is out of place, so the mark covers the closing word alone, as it does
for ``ENDW`` and ``ENDL``.
"""

from __future__ import annotations

import pytest

from tests.analysis.placed import placed


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        # the guide's UNTIL w/o REPEAT example: UNTIL ends the REPEAT before the WHILE inside it (000:19011-19019)
        pytest.param(
            'DIM master_dist\nREPEAT\n  WHILE master_dist = 0\n  INPUT "Distance", master_dist\n'
            "  UNTIL master_dist > 100\n  ENDW\n",
            [("E2013", 5, 3, "UNTIL")],
            id="until-in-a-while",
        ),
        pytest.param("DIM a\nUNTIL a > 1\n", [("E2013", 2, 1, "UNTIL")], id="until-alone"),
        # NEXT with a loop variable: error 2009 at NEXT, the variable's own error 2003 at the variable
        pytest.param("DIM i\nNEXT i\n", [("E2009", 2, 1, "NEXT"), ("E2003", 2, 6, "i")], id="next-with-a-variable"),
        # the closers without anything after them were already marked at their word
        pytest.param("DIM a\nWHILE a\nENDL\nENDW\n", [("E2014", 3, 1, "ENDL")], id="endl"),
    ],
)
def test_the_mark_covers_the_closing_word(source: str, expected: list[tuple[str, int, int, str]]) -> None:
    assert placed(source, "code", "line", "column", "text", codes="E") == expected
