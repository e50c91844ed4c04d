"""``[tool.mint.migrate]`` (``[migrate]`` in ``mint.toml``) gives ``mint-migrate``'s options their defaults, under
their long names; the command line wins; a bad value is one line with its place."""

from __future__ import annotations

import json
from pathlib import Path

from click.testing import CliRunner, Result

from mintlang.migrate.cli import migrate

V3 = "HMSPEED = 10\n"  # v4 spells it HOMESPEED


def mint_migrate(*arguments: str | Path) -> Result:
    return CliRunner().invoke(migrate, [str(argument) for argument in arguments])


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


def test_the_table_sets_the_report_format_and_the_target_controller(tmp_path: Path) -> None:
    write(tmp_path / "pyproject.toml", '[tool.mint.migrate]\nformat = "json"\ncontroller = "mintdrive"\n')
    program = write(tmp_path / "old" / "demo.mnt", V3)
    result = mint_migrate(program)
    assert result.exit_code == 0, result.output
    assert json.loads(result.stdout)["controller"] == "mintdrive"
    assert program.read_text(encoding="utf-8") == V3  # a dry run still


def test_the_shared_controller_is_the_default_target(tmp_path: Path) -> None:
    write(tmp_path / "mint.toml", 'controller = "nextmove-bx"\n[migrate]\nformat = "json"\n')
    result = mint_migrate(write(tmp_path / "demo.mnt", V3))
    assert json.loads(result.stdout)["controller"] == "nextmove-bx"


def test_the_command_line_wins_over_the_table(tmp_path: Path) -> None:
    write(tmp_path / "mint.toml", '[migrate]\nformat = "json"\n')
    result = mint_migrate("--format", "text", write(tmp_path / "demo.mnt", V3))
    assert result.exit_code == 0
    assert "+HOMESPEED = 10" in result.stdout


def test_a_flag_in_the_table_is_true_or_false(tmp_path: Path) -> None:
    write(tmp_path / "mint.toml", "[migrate]\nwrite = true\n")
    program = write(tmp_path / "demo.mnt", V3)
    assert mint_migrate(program).exit_code == 0
    assert "HOMESPEED = 10" in program.read_text(encoding="utf-8")
    settings = write(tmp_path / "mint.toml", "[migrate]\nwrite = 1\n")
    result = mint_migrate(program)
    assert (result.exit_code, result.stdout) == (2, "")
    assert result.stderr == f"mint-migrate: {settings.absolute()}:2:9: migrate.write: must be true or false\n"


def test_an_unknown_key_names_the_options_there_are(tmp_path: Path) -> None:
    settings = write(tmp_path / "mint.toml", "[migrate]\n\nwirte = true\n")
    result = mint_migrate(write(tmp_path / "demo.mnt", V3))
    assert result.exit_code == 2
    assert result.stderr.startswith(f"mint-migrate: {settings.absolute()}:3:1: migrate.wirte: unknown key (known: ")
    assert "write" in result.stderr and "version" not in result.stderr
