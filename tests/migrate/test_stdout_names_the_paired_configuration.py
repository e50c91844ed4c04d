"""``--stdout`` prints one file; a program named alone that pairs with its configuration file (``cell.cfg``
beside ``cell.mnt``) is migrated with it, as the controller runs the two together, so it is two files: the
refusal names the configuration file and how to see both, where it said only to name one file."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from mintlang.migrate.cli import migrate as command


def test_a_paired_program_is_refused_naming_its_configuration_file(tmp_path: Path) -> None:
    program, configuration = tmp_path / "cell.mnt", tmp_path / "cell.cfg"
    program.write_text("SP = 10\n")
    configuration.write_text("GN = 5\n")
    result = CliRunner().invoke(command, ["--stdout", str(program)])
    assert result.exit_code == 2
    assert result.stderr == (
        f"mint-migrate: --stdout prints one file, and {program} is migrated together with its configuration file "
        f"{configuration} (the controller runs them together): see both with --diff\n"
    )
    assert result.stdout == ""


def test_a_program_without_a_configuration_file_is_printed(tmp_path: Path) -> None:
    program = tmp_path / "cell.mnt"
    program.write_text("HMSPEED = 10\n")
    result = CliRunner().invoke(command, ["--stdout", "-q", str(program)])
    assert result.exit_code == 0
    assert result.stdout.endswith("HOMESPEED = 10\n")  # v4:11357: HMSPEED is HOMESPEED
