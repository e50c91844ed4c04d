"""A word neither Mint version knows is no sign of Mint v4.

The v3 guide's expanded I/O example writes ``X2.0 = 0`` for bit 2 of bank 0, X2 being its
abbreviation of XIO2 (v3:12747-12755). When the keyword database did not know X2, it was taken
for a v4-only keyword with a dot and made the whole application "already v4": left as it was,
the XIO lines beside it got no marker although Mint v4 has no XIO (X-IO-EXP). The guide's
misprint ``HMPSEED.2 = 10`` (v3:8708) is such a word neither version knows.
"""

from __future__ import annotations

from mintlang.migrate import migrate

GUIDE_XIO = (
    "XIO.1 = 1: REM Output to bank 1 (bit 8)\n"
    "? XIO.2 : REM Read inputs on Bank 2\n"
    "X2.0 = 0 : REM Clear bit 2 of bank 0\n"
)


def test_the_guide_s_xio_example_is_migrated() -> None:
    result = migrate(GUIDE_XIO)
    assert not result.already_v4
    assert [(item.rule, item.original_line) for item in result.manual] == [
        ("X-IO-EXP", 1),
        ("X-IO-EXP", 2),
        ("X-IO-EXP", 3),
    ]


def test_an_unknown_word_alone_does_not_make_a_file_v4() -> None:
    assert not migrate("HMPSEED.2 = 10\n").already_v4


def test_a_v4_only_keyword_with_a_dot_still_does() -> None:
    program = "HOMESPEED.0 = 10\n"
    result = migrate(program)
    assert result.already_v4 and result.text == program
