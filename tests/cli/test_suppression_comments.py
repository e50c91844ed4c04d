"""Suppression comments on the command line: every format, and a configuration file seen by several programs."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from mintlang.cli import main

# Line 1's unused variable is silenced; line 2's is reported.
PROGRAM = "DIM total : REM mint: ignore[W103]\nDIM spare\n"


def mint_check(*arguments: str | Path) -> str:
    result = CliRunner().invoke(main, ["check", *(str(argument) for argument in arguments)])
    assert result.exit_code == 0, result.output
    return result.stdout


@pytest.mark.parametrize(
    ("output_format", "reported", "silenced"),
    [
        ("text", "--> {path}:2:5", "--> {path}:1:"),
        ("github", "line=2,col=5", "line=1,"),
        ("json", '"line": 2', '"line": 1'),
        ("sarif", '"startLine": 2', '"startLine": 1'),
    ],
)
def test_every_format_leaves_the_silenced_finding_out(
    tmp_path: Path, output_format: str, reported: str, silenced: str
) -> None:
    path = tmp_path / "cell.mnt"
    path.write_text(PROGRAM, encoding="utf-8")
    output = mint_check("--format", output_format, path)
    assert reported.format(path=path) in output
    assert silenced.format(path=path) not in output


def test_a_configuration_suppression_is_unused_only_if_no_program_uses_it(tmp_path: Path) -> None:
    """shared is unused by b.mnt only: the comment silences b's W103, so it is used."""
    configuration = tmp_path / "machine.cfg"
    configuration.write_text("DIM shared : REM mint: ignore[W103]\n", encoding="utf-8")
    (tmp_path / "a.mnt").write_text("shared = 1\n", encoding="utf-8")
    (tmp_path / "b.mnt").write_text("PRINT 1\n", encoding="utf-8")
    arguments = ["--format", "json", "--config", configuration, tmp_path / "a.mnt", tmp_path / "b.mnt"]
    assert json.loads(mint_check(*arguments)) == []
    (tmp_path / "b.mnt").write_text("PRINT shared\n", encoding="utf-8")
    [unused] = json.loads(mint_check(*arguments))
    assert (unused["code"], unused["path"]) == ("W117", str(configuration))
