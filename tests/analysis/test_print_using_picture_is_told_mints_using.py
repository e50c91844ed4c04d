"""Other BASICs' ``PRINT USING "###.##"; x`` is told how Mint formats a number: the items first, then USING and
two digit counts, ``PRINT x USING 3, 2`` (000:15295-15296, 15313-15315).

Mint's USING takes the number of integer and fractional digits, not a picture, and pads the integer part
with zeroes (000:15315, 15330-15332: 123.5 USING 5,2 is 0123.50), where a picture pads with spaces: so the
rewrite is an unsafe fix, offered where one item follows the picture, its digits counted from the '#'s.
"""

from __future__ import annotations

import mintlang
from tests.analysis.checking import apply


def _error(line: str) -> tuple[str, mintlang.Diagnostic]:
    source = f"DIM x = 2.5\n{line}\n"
    (error,) = mintlang.check(source)
    return source, error


def test_a_picture_is_told_the_digit_counts_after_the_item() -> None:
    source, error = _error('PRINT USING "###.##"; x')
    assert error.code == "E2003"
    assert error.span.start == len('DIM x = 2.5\nPRINT USING "') - 1
    assert error.message == (
        "Syntax error: Mint's USING follows the items it formats and counts the digits, it takes no picture: "
        "PRINT x USING 3, 2"
    )
    (fix,) = error.fixes
    assert not fix.safe  # zeroes pad the integer part where the picture's spaces did
    assert apply(source, fix.edits) == "DIM x = 2.5\nPRINT x USING 3, 2\n"


def test_a_picture_without_a_point_gives_one_count() -> None:
    source, error = _error('? USING "####", x * 2')
    assert error.message.endswith("it takes no picture: ? x * 2 USING 4")
    assert apply(source, error.fixes[0].edits) == "DIM x = 2.5\n? x * 2 USING 4\n"


def test_several_items_are_told_without_a_fix() -> None:
    _, error = _error('PRINT USING "##.#"; x; x')
    assert error.message.endswith("it takes no picture: PRINT <items> USING <integer digits>, <fraction digits>")
    assert error.fixes == ()
