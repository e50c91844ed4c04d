"""A user name may begin with an underscore only when a letter or digit follows it.

Both guides give the rule in the same words: a name begins with a letter, or with an underscore
"as long as it is followed by an alphanumeric" (000:882-884, 001:1342), and show ``DIM _myVar2``
(000:895). So ``_`` alone and ``__x`` name nothing: written anywhere, they are a syntax error (2003,
"the statement is syntactically incorrect", 000:18921-18922) at the word, in Mint v4 and v3 alike.
"""

from __future__ import annotations

import pytest

import mintlang


def _errors(source: str, dialect: str = "v4") -> list[tuple[str, int, int]]:
    return [(d.code, d.span.start, d.span.end) for d in mintlang.check(source, dialect=dialect) if d.code[0] == "E"]


@pytest.mark.parametrize("dialect", ["v4", "v3"])
@pytest.mark.parametrize("name", ["_", "__x", "__1", "___"])
def test_an_underscore_followed_by_no_letter_or_digit_is_a_syntax_error(name: str, dialect: str) -> None:
    assert _errors(f"PRINT {name}\nEND\n", dialect) == [("E2003", 6, 6 + len(name))]


@pytest.mark.parametrize("name", ["_myVar2", "_1", "_a_", "_x__"])
def test_an_underscore_followed_by_a_letter_or_digit_begins_a_name(name: str) -> None:
    assert _errors(f"DIM {name} = 1\nPRINT {name}\nEND\n") == []


def test_the_message_says_what_the_name_lacks() -> None:
    (diagnostic,) = mintlang.check("DIM __x\nEND\n")
    assert diagnostic.message.endswith(
        "'__x' is not a valid name: an underscore that begins a name must be followed by a letter or a digit"
    )
