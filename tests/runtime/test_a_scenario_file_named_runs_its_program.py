"""``mint test cell.scenario.toml`` runs the test that scenario file holds: that of ``cell.mnt`` beside it.

README.md, "mint test": a program is a test when a scenario file named after it is beside it
(``cell.scenario.toml`` for ``cell.mnt``, any case); a scenario file with no program of its name
beside it is reported and exits 2. Named on the command line, the scenario file was read as a program
with no expectation, so ``mint test`` said no test was found (exit 5), though its program was there.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner, Result

from mintlang.cli import main
from tests.runtime.invoking import write

EXPECTS_TWO = '[[expect]]\nwhat = "a"\nequals = 2\n'


def _mint_test(*arguments: str | Path) -> Result:
    return CliRunner().invoke(main, ["test", "-j", "1", "--color", "never", *(str(argument) for argument in arguments)])


def test_a_scenario_file_named_runs_the_program_beside_it(tmp_path: Path) -> None:
    program = write(tmp_path, "Cell.MNT", "DIM a\na = 1 + 1\n")
    scenario = write(tmp_path, "cell.scenario.toml", EXPECTS_TWO)
    result = _mint_test(scenario)
    assert (result.exit_code, result.output.splitlines()[0]) == (0, f"PASSED {program}")


def test_a_program_and_its_scenario_file_both_named_run_it_once(tmp_path: Path) -> None:
    program = write(tmp_path, "cell.mnt", "DIM a\na = 1 + 1\n")
    scenario = write(tmp_path, "cell.scenario.toml", EXPECTS_TWO)
    result = _mint_test(program, scenario)
    assert (result.exit_code, result.output.count("PASSED")) == (0, 1)


def test_a_scenario_file_named_with_no_program_beside_it_is_reported_and_exits_2(tmp_path: Path) -> None:
    scenario = write(tmp_path, "conveyer.scenario.toml", EXPECTS_TWO)
    result = _mint_test(scenario)
    assert result.exit_code == 2
    assert f"mint test: {scenario}: no program conveyer.mnt beside it, so it runs nothing" in result.output


def test_a_scenario_file_with_no_program_named_and_in_a_folder_named_is_reported_once(tmp_path: Path) -> None:
    scenario = write(tmp_path, "conveyer.scenario.toml", EXPECTS_TWO)
    result = _mint_test(tmp_path, scenario)
    assert (result.exit_code, result.output.count("no program conveyer.mnt")) == (2, 1)


def test_a_scenario_file_with_no_program_is_reported_once_however_its_paths_are_spelt(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The folder by its absolute path and the file relative to the working folder are one file."""
    (tmp_path / "t").mkdir()
    write(tmp_path / "t", "lone.scenario.toml", EXPECTS_TWO)
    monkeypatch.chdir(tmp_path)
    result = _mint_test(tmp_path / "t", Path("t", "lone.scenario.toml"))
    assert (result.exit_code, result.output.count("no program lone.mnt")) == (2, 1)
