"""Other BASICs' ``CONST name = value`` is told Mint's way of naming a constant: a macro, ``DEFINE name = value``.

Macros make numerical constants (000:1460-1462): CONST is no Mint keyword (3007), and was offered no
Mint word, leaving its author to guess.
"""

from __future__ import annotations

import mintlang


def test_const_is_told_define() -> None:
    (diagnostic, *_) = mintlang.check("CONST layers = 5\nPRINT 1\n")
    assert diagnostic.code == "E3007"
    assert diagnostic.message.endswith("'CONST' is not a keyword (a named constant is a macro: DEFINE name = value)")
