"""A line far beyond the controller's 255 characters is reported, not analysed: memory stays near the input's size.

A 4 MB line of a million terms took 737 MB to check (issue 17, item 10); the lexer
now stops at ``MAX_TOKENS`` and makes the rest of the line one token.
"""

from __future__ import annotations

import tracemalloc

import mintlang
from mintlang.syntax.lexer import MAX_TOKENS, lex

TERMS = 250_000  # a 1 MB line: "a = 1 + 1 + ... + 1"
HUGE = "DIM a\na = " + " + ".join(["1"] * TERMS) + "\nPRINT a\n"


def test_a_huge_line_is_one_error_and_one_warning_and_the_lines_after_it_are_checked() -> None:
    found = sorted((d.code, d.message) for d in mintlang.check(HUGE + "PRINT b\n"))
    codes = [code for code, _ in found]
    assert codes == ["E2015", "E3001", "W111"]  # too complex; b undeclared on the last line; too long
    assert f"more than {MAX_TOKENS} tokens on one line" in found[0][1]


def test_the_tokens_of_a_huge_line_still_join_back_to_the_source() -> None:
    assert "".join(token.text for token in lex(HUGE).tokens) == HUGE


def test_checking_a_huge_line_takes_less_than_fifty_times_its_size_in_memory() -> None:
    mintlang.check("DIM a\n")  # the grammar and keyword database are loaded once, before
    mintlang.clear_caches()
    tracemalloc.start()
    try:
        mintlang.check(HUGE)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 50 * len(HUGE)
