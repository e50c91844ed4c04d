"""mint-migrate reads a program and its paired configuration file as one application, as mint check and
mint-run do: a folder's .cfg is no longer left in v3 while --check passes (a new user's trial)."""

from __future__ import annotations

import json
from pathlib import Path

from click.testing import CliRunner

from mintlang.migrate.cli import migrate

PROGRAM = "RESET.0\nMOVEA.0 = 10 : GO.0\nEND\n"  # already v4
CONFIGURATION = "SP = 100;\n"  # SP is Mint v3's abbreviation of SPEED


def _folder(tmp_path: Path) -> Path:
    (tmp_path / "cell.mnt").write_text(PROGRAM, encoding="utf-8")
    (tmp_path / "CELL.CFG").write_text(CONFIGURATION, encoding="utf-8")
    return tmp_path


def test_a_folder_run_migrates_the_configuration_with_its_program(tmp_path: Path) -> None:
    folder = _folder(tmp_path)
    assert CliRunner().invoke(migrate, ["--check", str(folder)]).exit_code == 1
    assert CliRunner().invoke(migrate, ["--write", str(folder)]).exit_code == 0
    assert (folder / "CELL.CFG").read_text(encoding="utf-8").endswith("\nSPEED = 100;\n")
    assert CliRunner().invoke(migrate, ["--check", str(folder)]).exit_code == 0


def test_a_program_and_its_configuration_named_together_are_one_application(tmp_path: Path) -> None:
    folder = _folder(tmp_path)
    result = CliRunner().invoke(migrate, ["--format", "json", str(folder / "cell.mnt"), str(folder / "CELL.CFG")])
    files = [entry["path"] for entry in json.loads(result.stdout)["files"]]
    assert files == [str(folder / "CELL.CFG"), str(folder / "cell.mnt")]  # the configuration first, once


def test_no_config_migrates_a_program_alone_as_mint_run_no_config_runs_it(tmp_path: Path) -> None:
    """The program reads ``a``, which its configuration file's assignment declares in Mint v3. Paired, M-DIM
    declares it once in the configuration file, which runs first; alone (--no-config), the program declares
    it itself and the configuration file is neither read nor written."""
    (tmp_path / "cell.mnt").write_text("PRINT a\n", encoding="utf-8")
    (tmp_path / "CELL.CFG").write_text("a = 5\n", encoding="utf-8")
    runner = CliRunner()
    assert runner.invoke(migrate, ["--write", "--no-config", str(tmp_path / "cell.mnt")]).exit_code == 0
    assert (tmp_path / "cell.mnt").read_text(encoding="utf-8") == "DIM a\nPRINT a\n"
    assert (tmp_path / "CELL.CFG").read_text(encoding="utf-8") == "a = 5\n"


def test_no_config_and_config_together_are_a_usage_error(tmp_path: Path) -> None:
    folder = _folder(tmp_path)
    result = CliRunner().invoke(
        migrate, ["--no-config", "--config", str(folder / "CELL.CFG"), str(folder / "cell.mnt")]
    )
    assert result.exit_code == 2
    assert "--no-config pairs none" in result.stderr
