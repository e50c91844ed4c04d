"""An output file (``--output-file``, ``--lcov``) never takes the place of an input or a Mint source.

A new user's trial wrote ``mint check --output-file k.mnt k.mnt`` and lost the program to its own report.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from mintlang.cli import main
from tests.cli.invoking import write

PROGRAM = "REM @expect a = 0\nDIM a\nPRINT a\n"


@pytest.mark.parametrize(
    "command",
    [
        ["check"],
        ["migrate"],
        ["test", "--format", "junit"],
    ],
    ids=["check", "migrate", "test"],
)
def test_the_report_is_refused_where_the_program_is(tmp_path: Path, command: list[str]) -> None:
    program = write(tmp_path / "k.mnt", PROGRAM)
    result = CliRunner().invoke(main, [*command, str(program), "--output-file", str(program)])
    assert result.exit_code == 2
    assert f"cannot write {program}: it is a Mint source file, not a report" in result.output
    assert program.read_text(encoding="utf-8") == PROGRAM


def test_mint_test_writes_neither_report_nor_tracefile_over_a_scenario(tmp_path: Path) -> None:
    program = write(tmp_path / "p.mnt", "DIM a\n")
    scenario = write(tmp_path / "p.scenario.toml", '[[expect]]\nwhat = "a"\nequals = 0\n')
    for option in (["--output-file", str(scenario)], ["--coverage", "--lcov", str(scenario)]):
        result = CliRunner().invoke(main, ["test", str(program.parent), *option])
        assert result.exit_code == 2
        assert f"cannot write {scenario}: it is also an input" in result.output
    assert scenario.read_text(encoding="utf-8").startswith("[[expect]]")
