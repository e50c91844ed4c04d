"""An axis list with nothing in it, ``GO[]``, is 2001, a parameter missing in the brackets (000:18909-18914).

The guide's examples leave a place empty between or after commas (``SPEED[0,,2]``, ``SPEED[0,1,]``);
``GO[]`` has no comma, so the message says the brackets are empty rather than naming commas.
"""

from __future__ import annotations

import pytest

import mintlang


def _errors(source: str, dialect: str) -> list[tuple[str, str]]:
    found = mintlang.check_application(source, dialect=dialect).program
    return [(d.code, d.message) for d in found if d.code[0] == "E"]


@pytest.mark.parametrize(("source", "dialect"), [("GO[]\n", "v4"), ("GO()\n", "mintmt")])
def test_empty_axis_brackets_say_there_is_no_axis_number(source: str, dialect: str) -> None:
    assert _errors(source, dialect) == [("E2001", "Missing parameter: no axis number between the brackets")]


def test_an_empty_place_between_commas_still_names_the_commas() -> None:
    """The guide's own example, ``SPEED[0,,2]=1000;`` (000:18912)."""
    assert _errors("SPEED[0,,2]=1000;\n", "v4") == [
        ("E2001", "Missing parameter: an axis number is missing between the commas")
    ]
