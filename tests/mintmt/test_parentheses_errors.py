"""A keyword's round brackets in MintMT (``POS(0)``) count as brackets when a line fails to parse.

2004 is a wrong number of brackets (000:18925-18928); any other statement the grammar refuses is a
syntax error, 2003 (000:18920-18922). MintMT lexes the ``(`` after a keyword as its own token, so a
failing line holding ``POS(0)`` read as one ``)`` too many.
"""

from __future__ import annotations

import mintlang


def _errors(source: str) -> list[tuple[str, str, int]]:
    """Each error's code, message and column (from 1) on its line."""
    found = mintlang.check_application(source, dialect="mintmt").program
    return [(d.code, d.message, d.span.start - source.rfind("\n", 0, d.span.start)) for d in found if d.code[0] == "E"]


def test_a_statement_after_a_block_ifs_do_is_a_syntax_error_not_a_bracket_too_many() -> None:
    """A block IF's DO ends its line (000:1594); ``PRINT`` at column 18 is what cannot follow."""
    assert _errors("IF POS(0) > 1 DO PRINT 1\n") == [("E2003", "Syntax error: unexpected 'PRINT'", 18)]


def test_a_missing_operand_after_a_keywords_brackets_is_a_syntax_error() -> None:
    """``x = POS(0) +`` has as many ``(`` as ``)``: the statement ends early, at column 13."""
    assert _errors("DIM x\nx = POS(0) +\n") == [("E2003", "Syntax error: unexpected end of the statement", 13)]


def test_one_bracket_too_many_after_a_keywords_brackets_is_still_2004() -> None:
    """``x = POS(0))`` has one ``)`` too many, the second one, at column 11 (000:18927-18928)."""
    assert _errors("DIM x\nx = POS(0))\n") == [("E2004", "Parentheses error: there is a ')' too many", 11)]
