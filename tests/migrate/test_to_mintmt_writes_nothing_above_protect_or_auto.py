"""``--to mintmt`` writes nothing above the PROTECT or AUTO that opens a file, as the v3 -> v4 migration does.

PROTECT must be the first line of the program, before any comment (v4:15393), and AUTO the first
command of the configuration file, REM lines included (v4:6647-6648); MintMT keeps both keywords.
A marker for that line goes right below it and says it marks the line above, ``(line above)``, so the
report, ``--verify`` and a second migration read it as marking line 1; a marker for the next line
still goes above that line, below the first one's.
"""

from __future__ import annotations

import pytest

from mintlang.migrate import MigrationResult
from mintlang.migrate.mintmt import to_mintmt
from mintlang.migrate.verification.model import Place
from mintlang.migrate.verification.runnable import flagged_places

_AXES = "REM MIGRATE: MT-ADDRESS: (line above) AXES is kept as v4 writes it: the notes show no MintMT form of it"
_EVENT = "REM MIGRATE: MT-NAME: event is a MintMT keyword: rename it in the whole application"


def _items(result: MigrationResult) -> list[tuple[str, int, int | None]]:
    return [(item.rule, item.line, item.original_line) for item in result.manual]


@pytest.mark.parametrize(
    ("program", "migrated"),
    [
        pytest.param("PROTECT tincan : AXES[0,1]\nDIM x\n", f"PROTECT tincan : AXES[0,1]\n{_AXES}\nDIM x\n", id="lf"),
        pytest.param(
            "PROTECT tincan : AXES[0,1]\r\nDIM x\r\n", f"PROTECT tincan : AXES[0,1]\r\n{_AXES}\r\nDIM x\r\n", id="crlf"
        ),
        pytest.param("PROTECT tincan : AXES[0,1]", f"PROTECT tincan : AXES[0,1]\n{_AXES}", id="no-line-end"),
    ],
)
def test_the_marker_of_the_protect_line_goes_below_it_and_marks_it(program: str, migrated: str) -> None:
    result = to_mintmt(program)
    assert result.text == migrated
    assert _items(result) == [("MT-ADDRESS", 1, 1)]


def test_the_marker_of_the_auto_line_goes_below_it_and_marks_it() -> None:
    result = to_mintmt("DIM y\n", config="AUTO : AXES[0,1]\n")
    assert result.configuration is not None
    assert result.configuration.text == f"AUTO : AXES[0,1]\n{_AXES}\n"
    assert _items(result.configuration) == [("MT-ADDRESS", 1, 1)]


def test_the_next_line_keeps_its_marker_above_it() -> None:
    result = to_mintmt("PROTECT tincan : AXES[0,1]\nDIM event\n")
    assert result.text == f"PROTECT tincan : AXES[0,1]\n{_AXES}\n{_EVENT}\nDIM event\n"
    assert _items(result) == [("MT-ADDRESS", 1, 1), ("MT-NAME", 4, 2)]


def test_verify_disables_the_protect_line_it_flags() -> None:
    assert flagged_places(to_mintmt("PROTECT tincan : AXES[0,1]\nDIM x\n")) == {Place("program", 1)}


@pytest.mark.parametrize(
    "program",
    [
        pytest.param("PROTECT tincan : AXES[0,1]\nDIM event\n", id="two-markers"),
        pytest.param("PROTECT tincan : AXES[0,1]", id="no-line-end"),
    ],
)
def test_a_second_migration_changes_nothing(program: str) -> None:
    first = to_mintmt(program)
    again = to_mintmt(first.text)
    assert again.text == first.text
    assert _items(again) == [(rule, line, line) for rule, line, _ in _items(first)]
