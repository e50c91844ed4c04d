"""``mint-migrate`` with no PATHS searches the current folder, as ``mint check``, ``mint format`` and ``mint test``
do (README, "mint check": with no PATHS the current directory is searched, as ruff does). It said "no .mnt or
.cfg files to migrate in " and named no folder.

HMSPEED is the v3 name of v4's HOMESPEED (000:98), so a folder holding it has something to rewrite."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from mintlang.migrate.cli import migrate as command


def test_no_paths_checks_the_programs_of_the_current_folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "press.mnt").write_text("HMSPEED.0 = 20\n")
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(command, ["--check", "--format", "json"])
    assert result.exit_code == 1, result.output  # the gate: something to rewrite
    assert '"path": "press.mnt"' in result.stdout


def test_no_paths_in_a_folder_without_programs_names_the_current_folder(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(command, [])
    assert result.exit_code == 2
    assert result.stderr.splitlines() == ["mint-migrate: no .mnt or .cfg files to migrate in ."]
