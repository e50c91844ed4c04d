"""``PROTECT <password>`` is the program's first command, as AUTO is the configuration's: W114 elsewhere.

The password "must be added as the first line of the program buffer before all
comments, similar to AUTO in the configuration buffer" (000:5291-5292, again in
the keyword's entry, 000:15393), and AUTO anywhere but first "will be ignored"
(000:6647-6648). Writing PROTECT turns the password checking on and off
(``PROTECT = _on``, 000:15420-15423): that form may stand anywhere.
"""

from __future__ import annotations

import pytest

import mintlang

# The guide's own example (000:15396-15412), shortened
GUIDE = 'PROTECT tincan\nREM\nREM Simple Mint Program\nREM\nDIM a\n?"Hello"\nLOOP\na = INKEY\n?a\nENDL\nEND\n'


def _found(program: str, config: str | None = None) -> tuple[list[tuple[str, int]], list[tuple[str, int]]]:
    """(code, offset) of each warning and error in the configuration file and in the program."""
    analysis = mintlang.check_application(program, config=config, controller="nextmove-pci")
    return [(d.code, d.span.start) for d in analysis.configuration], [(d.code, d.span.start) for d in analysis.program]


@pytest.mark.parametrize(
    "program",
    [GUIDE, "PROTECT tincan : REM the password\nPRINT 1\n", "\n  protect tincan\nPROTECT = _on\nPROTECT = _off\n"],
)
def test_a_password_first_in_the_program_and_writes_anywhere_are_accepted(program: str) -> None:
    assert _found(program) == ([], [])


def test_a_password_after_a_comment_is_ignored() -> None:
    configuration, program = _found("REM Simple Mint Program\nPROTECT tincan\nPRINT 1\n")
    assert (configuration, program) == ([], [("W114", 24)])


def test_a_second_password_and_one_after_a_statement_are_ignored() -> None:
    assert _found("PROTECT tincan\nPROTECT other\n") == ([], [("W114", 15)])
    assert _found("PRINT 1\nPROTECT tincan\n") == ([], [("W114", 8)])


def test_a_password_in_the_configuration_file_is_ignored() -> None:
    assert _found("PRINT 1\n", config="PROTECT tincan\n") == ([("W114", 0)], [])


def test_the_warning_says_where_the_password_belongs() -> None:
    (warning,) = mintlang.check("REM x\nPROTECT tincan\n")
    assert warning.message == (
        "PROTECT <password> is ignored unless it is the first command of the program file, before any REM"
    )
