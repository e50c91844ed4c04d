"""A number written with an exponent (``1E3``) is a syntax error (2003) told to be written out.

Mint reads a constant number as decimal, binary (a leading 0) or hexadecimal (0x) (000:743-745, 769-770, 799-800):
it has no exponent notation, and ``1E3`` is no number. The message says how the number is written where it is
one Mint can hold whole (up to ±16777215, 000:717-718).
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.checking import covered


@pytest.mark.parametrize(
    ("written", "told"),
    [
        ("1E3", "'1E3' is not a valid number: Mint numbers have no exponent, write 1000"),
        ("25e5", "'25e5' is not a valid number: Mint numbers have no exponent, write 2500000"),
        ("1E30", "'1E30' is not a valid number: Mint numbers have no exponent"),
    ],
)
def test_the_exponent_is_told(written: str, told: str) -> None:
    source = f"PRINT {written}\n"
    (diagnostic,) = mintlang.check(source)
    assert diagnostic.code == "E2003"
    assert covered(source, diagnostic) == written
    assert diagnostic.message == f"Syntax error: {told}"


def test_other_letters_after_digits_keep_their_message() -> None:
    (diagnostic,) = mintlang.check("PRINT 12abc\n")
    assert diagnostic.message == "Syntax error: '12abc' is not a valid number"
