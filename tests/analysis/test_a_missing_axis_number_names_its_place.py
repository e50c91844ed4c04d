"""Error 2001, a parameter missing in the brackets (000:18909-18914), says where the axis number is missing.

The guide's two examples leave a place empty between two commas (``SPEED[0,,2]=1000;``) and after the last
one (``SPEED[0,1,]=1000;``); the message names the place the author has to fill.
"""

from __future__ import annotations

import pytest

import mintlang


def _missing(source: str) -> list[str]:
    found = mintlang.check_application(source, dialect="v4").program
    return [d.message for d in found if d.code == "E2001"]


@pytest.mark.parametrize(
    ("source", "message"),
    [
        ("SPEED[0,,2]=1000;\n", "Missing parameter: an axis number is missing between the commas"),
        ("SPEED[0,1,]=1000;\n", "Missing parameter: an axis number is missing after the last comma"),
        ("SPEED[,1]=1000;\n", "Missing parameter: an axis number is missing before the first comma"),
    ],
)
def test_the_message_names_the_empty_place(source: str, message: str) -> None:
    assert _missing(source) == [message]
