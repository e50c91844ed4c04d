"""``ELSE IF``, as other BASICs write a further condition, is a syntax error (2003) told how Mint nests it.

An IF block has one ELSE, alone on its line, and an IF inside it is a block of its own with its own ENDIF
(000:1589-1600, 1633-1654), as ELSEIF is told (test_elseif_is_told_how_mint_writes_it). The message said
only that IF was unexpected. No fix is offered: the inner block's ENDIF has to go where its statements end.
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.checking import covered

MESSAGE = (
    "Syntax error: Mint has no ELSE IF: write ELSE on its own line, then an IF block of its own inside it, "
    "closed before the outer one"
)


@pytest.mark.parametrize(
    ("line", "dialect"),
    [
        pytest.param("ELSE IF x = 2 DO", "v4", id="do"),
        pytest.param("ELSE IF x = 2 THEN", "v4", id="then"),
        pytest.param("Else If x = 2 Then", "mintmt", id="mintmt"),
    ],
)
def test_else_if_is_told_the_nested_block(line: str, dialect: str) -> None:
    closer = "End If" if dialect == "mintmt" else "ENDIF"
    opener = "If x = 1 Then" if dialect == "mintmt" else "IF x = 1 DO"
    source = f"DIM x\n{opener}\n  x = 2\n{line}\n  x = 3\n{closer}\n"
    (diagnostic,) = mintlang.check(source, dialect=dialect)
    assert (diagnostic.code, covered(source, diagnostic), diagnostic.message) == ("E2003", line[:7], MESSAGE)
    assert diagnostic.fixes == ()


def test_else_then_an_if_after_a_colon_is_mint() -> None:
    assert mintlang.check("DIM x\nIF x = 1 DO\n  x = 2\nELSE : IF x = 2 THEN x = 3\nENDIF\n") == []
