"""Nothing the migrator writes goes above the PROTECT that opens a program.

PROTECT must be the first line of the program, before any comment (v4:15393); a line inserted above
it takes the protection away (v3:11092). A marker for the PROTECT line itself (X-PROTECT, for a v3
password v4 reads otherwise, v3:11089-11092, v4:15393-15394) therefore goes right below it and says
it marks the line above, ``(line above)``: the report, X-CHECK, ``--verify`` and a second migration
all read it as marking line 1. A marker for the next line still goes above that line, and what
the insertions add (DIM, AXES, the prologue notes) goes below the PROTECT line and its marker.
"""

from __future__ import annotations

import pytest

from mintlang.migrate import MigrationResult, migrate
from mintlang.migrate.verification.model import Place
from mintlang.migrate.verification.runnable import flagged_places

_PASSWORD = "REM MIGRATE: X-PROTECT: (line above) v4 reads the v3 password '{}' otherwise: " + (
    "choose one word of letters and digits"
)
_MY_PASS = _PASSWORD.format("my pass")


def _items(result: MigrationResult) -> list[tuple[str, int, int | None]]:
    return [(item.rule, item.line, item.original_line) for item in result.manual]


@pytest.mark.parametrize(
    ("program", "migrated"),
    [
        pytest.param("PROTECT my pass\nEND\n", f"PROTECT my pass\n{_MY_PASS}\nEND\n", id="lf"),
        pytest.param("PROTECT my pass\r\nEND\r\n", f"PROTECT my pass\r\n{_MY_PASS}\r\nEND\r\n", id="crlf"),
        pytest.param("PROTECT my pass\n", f"PROTECT my pass\n{_MY_PASS}\n", id="alone"),
        pytest.param("PROTECT my pass", f"PROTECT my pass\n{_MY_PASS}", id="no-line-end"),
    ],
)
def test_the_marker_of_the_protect_line_goes_below_it_and_marks_it(program: str, migrated: str) -> None:
    result = migrate(program, only=["X-PROTECT"])
    assert result.text == migrated
    assert _items(result) == [("X-PROTECT", 1, 1)]


@pytest.mark.parametrize(
    ("program", "migrated", "items"),
    [
        pytest.param(
            # v3 reads the rest of the line as the password (v3:11092); v4 reads PROTECT pw, then INCR = 5:
            # X-CHECK finds the line marked and adds no marker of its own
            "PROTECT pw : INCR = 5\nx = 1\n",
            f"PROTECT pw : INCR = 5\n{_PASSWORD.format('pw : INCR = 5')}\nDIM x\nx = 1\n",
            [("X-PROTECT", 1, 1)],
            id="x-check-sees-it",
        ),
        pytest.param(
            # the DIM goes below the PROTECT line's marker; the next line's marker stays above that line
            "PROTECT my pass\nPRINT foo(1)\nPRINT b\n",
            f"PROTECT my pass\n{_MY_PASS}\nDIM b\n"
            "REM MIGRATE: M-DIM: array 'foo' is used but never dimensioned\nPRINT foo(1)\nPRINT b\n",
            [("X-PROTECT", 1, 1), ("M-DIM", 5, 2)],
            id="dim-and-the-next-line",
        ),
    ],
)
def test_every_rule_leaves_protect_first(program: str, migrated: str, items: list[tuple[str, int, int]]) -> None:
    result = migrate(program)
    assert result.text == migrated
    assert _items(result) == items


def test_the_prologue_notes_go_below_protect() -> None:
    result = migrate("PROTECT my pass\nMOVEA = 10 : GO\n")
    lines = result.text.splitlines()
    assert lines[:2] == ["PROTECT my pass", _MY_PASS]
    assert lines[-2:] == ["AXES[0,1,2]", "MOVEA = 10 : GO"]
    assert _items(result)[0] == ("X-PROTECT", 1, 1)


def test_verify_disables_the_protect_line_it_flags() -> None:
    result = migrate("PROTECT pw : INCR = 5\nx = 1\n")
    assert flagged_places(result) == {Place("program", 1)}


@pytest.mark.parametrize(
    "program",
    [
        pytest.param("PROTECT my pass\nx = 1\n", id="dim"),
        pytest.param("PROTECT pw : INCR = 5\nPRINT foo(1)\n", id="two-markers"),
        pytest.param("PROTECT my pass", id="no-line-end"),
    ],
)
def test_a_second_migration_changes_nothing(program: str) -> None:
    first = migrate(program)
    again = migrate(first.text)
    assert again.text == first.text
    assert [(item.rule, item.line) for item in again.manual] == [(item.rule, item.line) for item in first.manual]
