"""``--write`` never replaces a file that changed after it was read: an edit saved while the
migration ran is kept, the file is named, the other files are written, and the exit status
is 2. The test is on the bytes, so an edit that keeps the size and the time stamp counts."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from click.testing import CliRunner, Result

from mintlang import atomic
from mintlang.migrate import applications
from mintlang.migrate.cli import migrate as command
from mintlang.migrate.model import MigrationResult

V3 = "DIM a(2)\nPRINT a(1)\nSTOP\n"
V4 = "AXES[0,1,2]\nDIM a(2)\nPRINT a(1)\nSTOP\n"
EDIT = "DIM b\nPRINT b\nSTOP\n"  # what the user saves meanwhile: same size as V3


def run(*arguments: object) -> Result:
    return CliRunner().invoke(command, [str(argument) for argument in arguments])


@pytest.fixture
def edited_meanwhile(monkeypatch: pytest.MonkeyPatch) -> list[Path]:
    """Paths whose files the "user" rewrites with EDIT once their migration is done, keeping
    the time stamp, as a save within the same clock tick would."""
    edited: list[Path] = []
    migrate = applications.migrate

    def migrate_then_edit(program: str, **options: object) -> MigrationResult:
        result = migrate(program, **options)  # type: ignore[arg-type]
        for path in edited:
            status = path.stat()
            path.write_text(EDIT)
            os.utime(path, ns=(status.st_atime_ns, status.st_mtime_ns))
        return result

    monkeypatch.setattr(applications, "migrate", migrate_then_edit)
    return edited


def test_a_file_edited_during_the_migration_is_kept_and_named(tmp_path: Path, edited_meanwhile: list[Path]) -> None:
    first, edited, last = (tmp_path / name for name in ("a.mnt", "b.mnt", "c.mnt"))
    for path in (first, edited, last):
        path.write_text(V3)
    edited_meanwhile.append(edited)
    result = run("--write", tmp_path)
    assert result.exit_code == 2
    assert result.stderr.splitlines() == [
        f"mint-migrate: {edited} changed since it was read: not written, so the edit is kept; migrate again",
        f"mint-migrate: 2 of 3 files written; not written: {edited}",
    ]
    assert (first.read_text(), edited.read_text(), last.read_text()) == (V4, EDIT, V4)


def test_an_edited_configuration_file_stops_its_program_being_written(
    tmp_path: Path, edited_meanwhile: list[Path]
) -> None:
    """The program was migrated with the configuration's old variables: written, it could be
    wrong for the new ones, so neither file of the application is written."""
    config, program = tmp_path / "app.cfg", tmp_path / "app.mnt"
    config.write_text("AUTO\nDIM a\n")
    program.write_text("b = 1\nPRINT b\n")
    edited_meanwhile.append(config)
    result = run("--write", "--config", config, program)
    assert result.exit_code == 2
    assert f"mint-migrate: {config} changed since it was read: not written" in result.stderr
    assert program.read_text() == "b = 1\nPRINT b\n" and config.read_text() == EDIT


def test_the_last_check_is_made_right_before_the_rename(tmp_path: Path) -> None:
    path = tmp_path / "a.mnt"
    path.write_text(EDIT)
    with pytest.raises(atomic.Stale):
        atomic.write(path, V4.encode(), expected=V3.encode())
    assert path.read_text() == EDIT
    assert [p.name for p in tmp_path.iterdir()] == ["a.mnt"]  # its temporary file is gone
