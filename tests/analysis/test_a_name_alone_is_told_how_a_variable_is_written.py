"""A name standing alone as a statement, resembling no keyword, is told how a variable is written.

Error 3007 is a word Mint does not know as a keyword (000:19111-19116), and the guide tells the reader
to check the spelling and the abbreviation. A name alone is often a variable the author meant to give a
value (``a`` for ``a = …``, 000:877-879): the message says that too, since a declared variable is
still not a statement.
"""

from __future__ import annotations

import pytest

import mintlang


def _not_defined(source: str) -> list[str]:
    return [d.message for d in mintlang.check_application(source, dialect="v4").program if d.code == "E3007"]


@pytest.mark.parametrize(
    ("source", "message"),
    [
        pytest.param(
            "DIM a\na\n",
            "Keyword not defined: 'a' is not a keyword (check the spelling and the abbreviation; a variable alone "
            "is no statement: give it a value, a = …)",
            id="a-declared-variable",
        ),
        # a name that resembles a keyword is offered that keyword, as before
        pytest.param("SPEDD\n", "Keyword not defined: 'SPEDD' is not a keyword (did you mean 'SPEED'?)", id="a-typo"),
    ],
)
def test_the_message_says_how_a_variable_is_given_a_value(source: str, message: str) -> None:
    assert _not_defined(source) == [message]
