"""ELSEIF, another BASIC's word, is error 3007 told how Mint writes it, and offered no respelling.

An IF block has one ELSE, which stands on its own line, and an IF nests inside it with its own ENDIF
(000:1589-1600, 1633-1654). ELSEIF resembles ELSE, and ``--fix --unsafe-fixes`` wrote ``ELSE x = 2``,
a syntax error (2003) in place of the 3007 and a condition turned into an assignment.
"""

from __future__ import annotations

import mintlang

SOURCE = "DIM x\nIF x = 1 DO\n  x = 2\nELSEIF x = 2\n  x = 3\nENDIF\n"


def test_elseif_is_not_offered_else() -> None:
    (diagnostic,) = mintlang.check(SOURCE)
    assert diagnostic.code == "E3007"
    assert diagnostic.fixes == ()
    assert "did you mean" not in diagnostic.message


def test_the_message_says_how_the_block_is_written() -> None:
    (diagnostic,) = mintlang.check(SOURCE)
    assert diagnostic.message.endswith(
        "'ELSEIF' is not a keyword (an IF block has no ELSEIF: write ELSE on its own line, "
        "then an IF block of its own inside it, closed before the outer one)"
    )
