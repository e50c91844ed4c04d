"""Visual Basic's ``DO .. LOOP UNTIL`` is told Mint's loops, not that DO is a variable or UNTIL unexpected.

Mint's loops are FOR .. NEXT, REPEAT .. UNTIL, WHILE .. ENDW and LOOP .. ENDL (000:1707, 1747, 1778, 1797).
DO only follows an IF's condition (000:1594-1600), so a statement that starts with it is a syntax error
(000:18920-18924), not a keyword used as a variable (2006, 000:18935-18943); LOOP .. ENDL loops for ever
(000:1797-1799) and takes no condition: a loop tested at its end is REPEAT .. UNTIL (000:1748-1755).
"""

from __future__ import annotations

import mintlang
from tests.analysis.checking import covered

SOURCE = "DIM a = 0\nDO\n  a = a + 1\nLOOP UNTIL a > 3\n"


def _errors(source: str) -> list[tuple[str, str, str]]:
    return [(d.code, covered(source, d), d.message) for d in mintlang.check(source) if d.severity.value == "error"]


def test_do_and_loop_until_are_told_the_loop_mint_has() -> None:
    assert _errors(SOURCE) == [
        ("E2003", "DO", "Syntax error: Mint has no DO loop: write REPEAT .. UNTIL, WHILE .. ENDW or LOOP .. ENDL"),
        (
            "E2003",
            "UNTIL",
            "Syntax error: LOOP .. ENDL loops for ever and takes no condition: "
            "a loop tested at its end is REPEAT .. UNTIL",
        ),
    ]


def test_do_while_is_told_too() -> None:
    source = "DIM a = 0\nDO WHILE a < 3\n  a = a + 1\nLOOP\n"
    assert _errors(source)[0][1:] == (
        "DO",
        "Syntax error: Mint has no DO loop: write REPEAT .. UNTIL, WHILE .. ENDW or LOOP .. ENDL",
    )
