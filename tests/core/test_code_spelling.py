"""The controller's error numbers are written in four digits, so a code prefix selects one family only.

The controller prints its own codes with four digits (R0003, C0002); E0002 "Axis specified out
of range" and E2014 "Incorrect loop terminator" are distinct codes that no prefix confuses.
"""

from __future__ import annotations

import pytest

from mintlang import check
from mintlang.codes import code_named, error_code, known_codes, selector


@pytest.mark.parametrize(
    ("number", "code"), [(2, "E0002"), (17, "E0017"), (108, "E0108"), (500, "E0500"), (2014, "E2014")]
)
def test_an_error_number_is_written_in_four_digits(number: int, code: str) -> None:
    assert error_code(number) == code


def test_diagnostics_carry_the_four_digit_code() -> None:
    found = check("SPEED.12 = 1\n", controller="nextmove-bx")
    assert [(d.code, d.mint_error) for d in found] == [("E0002", 2)]


def test_success_is_no_code() -> None:
    assert not any(code.startswith("E-") for code in known_codes())


@pytest.mark.parametrize(
    ("entry", "read_as"),
    [
        ("E2", "E2"),  # a prefix: E2000 to E2021
        ("e20", "E20"),  # a prefix too: E2000 to E2009
        ("E00", "E00"),  # the errors below 100
        ("E0002", "E0002"),
        ("E17", "E0017"),  # begins no code: the manual's spelling of error 17
        ("E108", "E0108"),
        ("E5", "E0005"),
        ("W1", "W1"),
        ("i201", "I201"),
    ],
)
def test_a_selector_is_a_prefix_of_four_digit_codes_or_else_a_short_spelling(entry: str, read_as: str) -> None:
    assert selector(entry) == read_as


def test_the_prefix_e2_selects_the_compilers_mismatch_errors_and_not_error_2() -> None:
    selected = {code for code in known_codes() if code.startswith(selector("E2"))}
    assert selected == {f"E{number}" for number in range(2000, 2022)}


def test_the_short_spellings_that_stay_prefixes_are_the_four_the_help_names() -> None:
    """Short spellings of known errors that begin a four-digit code: ``--select`` reads them as prefixes."""
    short = {f"E{int(code[1:])}" for code in known_codes() if code.startswith("E") and int(code[1:]) < 1000}
    prefixes = {entry for entry in short if selector(entry) == entry}
    assert prefixes == {"E2", "E3", "E20", "E30"}


@pytest.mark.parametrize("entry", ["E999", "E109", "X", "W999", "E0000"])
def test_a_selector_that_selects_nothing_is_refused(entry: str) -> None:
    with pytest.raises(ValueError, match="is no code"):
        selector(entry)


@pytest.mark.parametrize(
    ("text", "code"),
    [("E2", "E0002"), ("e17", "E0017"), ("E20", "E0020"), ("E2014", "E2014"), ("W103", "W103"), (" i201 ", "I201")],
)
def test_a_named_code_is_exact_and_takes_either_spelling(text: str, code: str) -> None:
    assert code_named(text) == code


@pytest.mark.parametrize("text", ["W1", "E", "E999", "E02", "W103X", ""])
def test_a_prefix_or_an_unknown_number_names_no_code(text: str) -> None:
    assert code_named(text) is None
