"""``LET a = 1``, old BASIC's assignment, is error 3007 told that Mint assigns without LET.

Mint gives a variable a value with the variable, ``=`` and the value (``newPos = 2``, 000:917-922); LET is no
keyword (3007, 000:19111-19115), and it resembles none closely enough to offer one.
"""

from __future__ import annotations

import mintlang


def test_let_is_told_the_assignment_without_it() -> None:
    (diagnostic,) = mintlang.check("DIM a\nLET a = 1\nPRINT a\n")
    assert diagnostic.code == "E3007"
    assert diagnostic.message.endswith("'LET' is not a keyword (Mint assigns without LET: leave it out)")
    assert diagnostic.fixes == ()
