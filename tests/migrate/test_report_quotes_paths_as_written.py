"""The text report names a file as it is spelt: rich reads ``:100:`` as the emoji code of 💯, so a
path holding one (``release:100:final``) was shown with the emoji in its place."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from mintlang.migrate.cli import migrate as command


def test_a_path_holding_an_emoji_code_is_reported_as_written(tmp_path: Path) -> None:
    folder = tmp_path / "release:100:final"
    folder.mkdir()
    path = folder / "prog.mnt"
    path.write_text("LOAD 3\n")  # X-HOST: a manual item at the line it marks, under its REM
    result = CliRunner().invoke(command, ["--controller", "mintdrive", "--only", "X-HOST", str(path)])
    assert f"{path}:2 (original line 1): X-HOST" in result.stdout
    assert "💯" not in result.stdout
