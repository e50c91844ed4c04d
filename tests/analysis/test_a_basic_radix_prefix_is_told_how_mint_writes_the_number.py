"""``&H1F``, ``&B101`` and ``&O17``, other BASICs' hexadecimal, binary and octal numbers, are syntax errors (2003)
told how Mint writes the number, with that as a safe fix: the value is the same.

Mint's ``&`` is its bitwise AND (000:1286-1289), so ``&H1F`` read as an AND with nothing before it and was told
that '&' cannot be used as a variable. Mint v4 writes hexadecimal with ``0x`` (0xF2FA is 62202, 000:769-772),
binary with a leading zero (011011 is 27, 000:743-747; v3 alike, 001:1185) and has no octal; the v3 guide has
no hexadecimal numbers at all, so there the number is written in decimal.
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.checking import apply, covered

DECLARED = "DIM a\n"


def _only(line: str, dialect: str = "v4") -> tuple[str, mintlang.Diagnostic]:
    source = DECLARED + line + "\nPRINT a\n"
    (diagnostic,) = mintlang.check(source, dialect=dialect)
    return source, diagnostic


@pytest.mark.parametrize(
    ("line", "number", "message", "fixed"),
    [
        pytest.param("a = &H1F", "&H1F", "Mint writes a hexadecimal number with 0x: 0x1F", "a = 0x1F", id="hex"),
        pytest.param(
            "a = &hf2fa", "&hf2fa", "Mint writes a hexadecimal number with 0x: 0xf2fa", "a = 0xf2fa", id="hex-lower"
        ),
        pytest.param(
            "OUT = a + &HFF_00",
            "&HFF_00",
            "Mint writes a hexadecimal number with 0x: 0xFF_00",
            "OUT = a + 0xFF_00",
            id="hex-in-a-sum",
        ),
        pytest.param(
            "a = &B11011", "&B11011", "Mint writes a binary number with a leading 0: 011011", "a = 011011", id="binary"
        ),
        # 17 in octal is 1 * 8 + 7 = 15
        pytest.param("a = &O17", "&O17", "Mint has no octal numbers: write 15", "a = 15", id="octal"),
    ],
)
def test_the_number_is_told_mints_writing_with_a_safe_fix(line: str, number: str, message: str, fixed: str) -> None:
    source, diagnostic = _only(line)
    assert (diagnostic.code, covered(source, diagnostic)) == ("E2003", number)
    assert diagnostic.message == f"Syntax error: {message}"
    (fix,) = diagnostic.fixes
    assert fix.safe
    assert apply(source, fix.edits) == DECLARED + fixed + "\nPRINT a\n"


def test_mint_v3_is_told_the_decimal_value() -> None:
    # 1F is 1 * 16 + 15 = 31
    source, diagnostic = _only("a = &H1F", "v3")
    assert diagnostic.message == "Syntax error: Mint v3 has no hexadecimal numbers: write 31"
    (fix,) = diagnostic.fixes
    assert apply(source, fix.edits) == DECLARED + "a = 31\nPRINT a\n"


def test_digits_the_prefix_does_not_take_are_not_rewritten() -> None:
    _, diagnostic = _only("a = &B102")
    assert "binary" not in diagnostic.message


def test_an_and_between_values_is_still_mints_and() -> None:
    assert mintlang.check(DECLARED + "DIM H1F = 3\na = 5 &H1F\nPRINT a\n") == []
