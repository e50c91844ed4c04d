"""A v3 user variable named like a v4 keyword the migrator also writes (``homespeed``: v3 had
HMSPEED, which v4 renamed HOMESPEED, v4:98) is renamed like any other reserved name, and does
not make its file look like Mint v4."""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate, shows_v4
from mintlang.semantic.units import Unit

# Ten significant characters: "homespeed" keeps eight and gets "_u" (as feedrate -> feedrate_u).
RENAMED = "homespee_u"


def test_an_assigned_and_read_homespeed_is_renamed_and_declared() -> None:
    source = "REM v3 cell\nhomespeed = 0\ncount = 3\nMA = 100 : GO\nPRINT homespeed + count\n"
    text = migrate(source, controller="nextmove-pci").text
    assert "homespeed" not in text.lower()
    assert f"DIM {RENAMED}\n" in text and "DIM count\n" in text
    assert f"{RENAMED} = 0\ncount = 3\nMOVEA = 100 : GO\nPRINT {RENAMED} + count\n" in text


def test_a_file_using_homespeed_only_as_a_variable_is_not_taken_for_v4() -> None:
    result = migrate("homespeed = 0\nPRINT homespeed\n", controller="nextmove-pci")
    assert not result.already_v4
    assert result.text == f"DIM {RENAMED}\n{RENAMED} = 0\nPRINT {RENAMED}\n"


@pytest.mark.parametrize(
    ("source", "v4"),
    [
        ("homespeed = 0\nPRINT homespeed\n", False),  # assigned, then read: a v3 variable
        ("HOMESPEED.0 = 10\n", True),  # with an axis: no variable takes one
        ("PRINT HOMESPEED\n", True),  # read, never assigned: v3 rejects an undeclared read
        ("HOMESPEED = 10\n", True),  # only assigned: what the migrator writes for HMSPEED = 10
        ("INPUTMODE = INPUTMODE | 128\n", True),  # read only in its own assignment: before declared
    ],
)
def test_which_uses_of_a_v4_only_keyword_show_v4(source: str, v4: bool) -> None:
    assert shows_v4({Unit.PROGRAM: source}, "nextmove-pci") is v4


def test_the_renamed_keyword_is_left_alone_beside_the_users_variable() -> None:
    """HMSPEED becomes the HOMESPEED keyword (axis 1), the user's homespeed its own name."""
    result = migrate("HMSPEED.1 = 4\nhomespeed = 2\nPRINT homespeed\n", controller="nextmove-pci")
    assert "HOMESPEED.1 = 4\n" in result.text
    assert f"{RENAMED} = 2\nPRINT {RENAMED}\n" in result.text
