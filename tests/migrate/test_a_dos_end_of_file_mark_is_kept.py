"""A Ctrl-Z (0x1A) ending a v3 file is the end-of-file mark DOS editors wrote (the v3 guide has files end
with one), not a line of the program: the migration keeps it last, byte for byte, and neither flags it
(no X-COMMENTED "unexpected character") nor counts it as an unreadable line."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from mintlang.migrate import migrate
from mintlang.migrate.cli import migrate as command

V3 = "DIM a(2)\r\nPRINT a(1)\r\nSTOP\r\n"
# v3 gave every program three axes; v4 must be told, in the file's own line ends
V4 = "AXES[0,1,2]\r\nDIM a(2)\r\nPRINT a(1)\r\nSTOP\r\n"


def test_the_mark_stays_last_and_nothing_is_flagged() -> None:
    result = migrate(V3 + "\x1a")
    assert result.text == V4 + "\x1a"
    assert (result.manual, result.errors) == ((), ())


def test_the_mark_after_a_last_line_without_a_line_end_stays_on_it() -> None:
    result = migrate("DIM a(2)\nSTOP\x1a\x1a")
    assert result.text == "AXES[0,1,2]\nDIM a(2)\nSTOP\x1a\x1a"
    assert (result.manual, result.errors) == ((), ())


def test_the_changes_point_at_the_text_they_replace() -> None:
    source = "HMSPEED = 10\n\x1a"
    result = migrate(source, controller="mintdrive", only=["M-REN"])
    assert result.text == "HOMESPEED = 10\n\x1a"
    change = result.changes[0]
    assert source[change.span.start : change.span.end] == change.original == "HMSPEED"


def test_a_ctrl_z_inside_the_program_is_still_flagged() -> None:
    """Only the end of the file is the mark's place; one inside a line is a stray character."""
    result = migrate("DIM a(2)\nPRINT a(1)\x1a\nSTOP\n")
    assert [item.rule for item in result.manual] == ["X-COMMENTED"]


def test_write_keeps_every_byte_of_the_file(tmp_path: Path) -> None:
    path = tmp_path / "old.mnt"
    path.write_bytes((V3 + "\x1a").encode())
    result = CliRunner().invoke(command, ["--write", str(path)])
    assert result.exit_code == 0
    assert "0 manual items, 0 unreadable lines" in result.stdout
    assert path.read_bytes() == (V4 + "\x1a").encode()


def test_verify_runs_both_programs_without_the_mark(tmp_path: Path) -> None:
    """The controller was never sent the mark: a v3 run that met it would stop on a syntax error."""
    path = tmp_path / "old.mnt"
    path.write_bytes(b'OUT0 = 1\r\nPRINT "ready"\r\n\x1a')
    result = CliRunner().invoke(command, ["--verify", str(path)])
    assert result.exit_code == 0
    assert f"{path}: equivalent" in result.stdout
