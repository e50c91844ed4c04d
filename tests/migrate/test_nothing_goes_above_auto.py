"""Nothing the migrator writes goes above the AUTO that opens a file.

AUTO starts the application at power-up only as the first command of the configuration file, REM
lines included (v4:6647-6648, v3:5838). A marker for the AUTO line itself (X-PLATFORM: the v4 quick
reference has no AUTO on a NextMove PCI, v4:17495) therefore goes right below it and says it marks
the line above, ``(line above)``, as one for an opening PROTECT does. When code follows AUTO on its
line, the line is broken after AUTO (a line end separates statements as ``:`` does, v4:5674-5692):
AUTO's marker goes right below it, a marker for the code right above the code. A program that starts
with AUTO keeps it first too: the migrator knows a file's role from its name alone, and the
controller ignores an AUTO there (v4:6648) wherever it stands.
"""

from __future__ import annotations

import pytest

from mintlang.migrate import MigrationResult, migrate
from mintlang.migrate.verification.model import Place
from mintlang.migrate.verification.runnable import flagged_places

_PLATFORM = "REM MIGRATE: X-PLATFORM: (line above) AUTO is not available on NextMove PCI"
_FOO = "REM MIGRATE: M-DIM: array 'foo' is used but never dimensioned"


def _items(result: MigrationResult) -> list[tuple[str, int, int | None]]:
    return [(item.rule, item.line, item.original_line) for item in result.manual]


@pytest.mark.parametrize(
    ("config", "migrated"),
    [
        pytest.param("AUTO\nEND\n", f"AUTO\n{_PLATFORM}\nEND\n", id="lf"),
        pytest.param("AUTO\r\nEND\r\n", f"AUTO\r\n{_PLATFORM}\r\nEND\r\n", id="crlf"),
        pytest.param("AUTO", f"AUTO\n{_PLATFORM}", id="no-line-end"),
        pytest.param("AUTO : REM run on power up\n", f"AUTO : REM run on power up\n{_PLATFORM}\n", id="a-comment"),
    ],
)
def test_the_marker_of_the_auto_line_goes_below_it_and_marks_it(config: str, migrated: str) -> None:
    result = migrate("END\n", config=config, only=["X-PLATFORM"])
    assert result.configuration is not None
    assert result.configuration.text == migrated
    assert _items(result.configuration) == [("X-PLATFORM", 1, 1)]


def test_code_after_auto_gets_its_marker_between_auto_and_the_code() -> None:
    result = migrate("END\n", config="AUTO : PRINT foo(1)\n", only=["X-PLATFORM", "M-DIM"])
    assert result.configuration is not None
    assert result.configuration.text == f"AUTO\n{_PLATFORM}\n{_FOO}\nPRINT foo(1)\n"
    assert _items(result.configuration) == [("X-PLATFORM", 1, 1), ("M-DIM", 4, 1)]


@pytest.mark.parametrize(
    ("program", "controller", "migrated"),
    [
        pytest.param("AUTO : PRINT foo(1)\nEND\n", "mintdrive", f"AUTO\n{_FOO}\nPRINT foo(1)\nEND\n", id="code-after"),
        pytest.param("AUTO\nPRINT foo(1)\n", "nextmove-pci", f"AUTO\n{_PLATFORM}\n{_FOO}\nPRINT foo(1)\n", id="alone"),
    ],
)
def test_a_program_that_starts_with_auto_keeps_it_first(program: str, controller: str, migrated: str) -> None:
    assert migrate(program, controller=controller, only=["X-PLATFORM", "M-DIM"]).text == migrated


def test_verify_disables_the_auto_line_it_flags() -> None:
    result = migrate("END\n", config="AUTO : PRINT foo(1)\n", only=["X-PLATFORM", "M-DIM"])
    assert flagged_places(result) == {Place("configuration", 1), Place("configuration", 4)}


@pytest.mark.parametrize(
    ("program", "config"),
    [
        pytest.param("END\n", "AUTO\nEND\n", id="alone"),
        pytest.param("END\n", "AUTO : PRINT foo(1)\n", id="code-after"),
        pytest.param("AUTO : PRINT foo(1)\nEND\n", None, id="program"),
    ],
)
def test_a_second_migration_changes_nothing(program: str, config: str | None) -> None:
    first = migrate(program, config=config)
    again = migrate(first.text, config=first.configuration.text if first.configuration is not None else None)
    assert again.text == first.text
    if first.configuration is not None:
        assert again.configuration is not None
        assert again.configuration.text == first.configuration.text
