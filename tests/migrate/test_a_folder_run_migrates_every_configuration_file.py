"""A configuration file in a migrated folder that no program pairs with (the v3 guide's ``3AXIS.CFG``
beside a program of another name, 001:4796) is migrated on its own, as when it is named: left in v3, it
would pass ``--check`` and fail on the controller. One a program pairs with is migrated with it, once."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner, Result

from mintlang.migrate.cli import migrate as command

V3 = "DIM a(2)\nPRINT a(1)\nSTOP\n"
V4 = "AXES[0,1,2]\nDIM a(2)\nPRINT a(1)\nSTOP\n"  # v3 gave a program three axes; v4 must be told


def run(*arguments: object) -> Result:
    return CliRunner().invoke(command, [str(argument) for argument in arguments])


def test_a_configuration_file_no_program_claims_is_migrated_alone(tmp_path: Path) -> None:
    (tmp_path / "main.mnt").write_text(V3)
    configuration = tmp_path / "3AXIS.CFG"
    configuration.write_bytes(b"SF = 2000\r\n")  # SF is v3's abbreviation of SCALE (001:79)
    assert run("--check", tmp_path).exit_code == 1
    result = run("--write", tmp_path)
    assert result.exit_code == 0
    assert configuration.read_bytes() == b"AXES[0,1,2]\r\nSCALE = 2000\r\n"
    assert (tmp_path / "main.mnt").read_text() == V4
    assert run("--check", tmp_path).exit_code == 0


def test_a_folder_holding_only_a_configuration_file_is_migrated(tmp_path: Path) -> None:
    (tmp_path / "system.cfg").write_text("SF = 2000\n")
    result = run("--check", tmp_path)
    assert result.exit_code == 1
    assert "1 file: 1 changed" in result.stdout


def test_a_paired_configuration_file_is_migrated_once_with_its_program(tmp_path: Path) -> None:
    (tmp_path / "cell.mnt").write_text(V3)
    (tmp_path / "cell.cfg").write_text("SF = 2000\n")
    result = run("--color", "never", tmp_path)
    assert result.exit_code == 0
    # the configuration file runs first (001:4782): the AXES written there serves the program as well
    assert "2 files: 1 changed, 1 unchanged" in result.stdout
    assert result.stdout.count("+++ b/") == 1
