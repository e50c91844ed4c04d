"""``mint test`` warns of each ``REM @sim``/``REM @expect`` line in a configuration file, as mint-run does.

Directives are read from the program only (runtime/scenario/README.md, "Directives in the program"), and
they exist so that "a mistyped check never passes unnoticed". One in the configuration file is not applied:
the warning names it at its file, line and column (that of its ``@``, from 1, counted by hand), on standard
error once, and in each report that runs it. A program whose only ``@expect`` lines are there was meant to
be a test, so it is one, in error, rather than left out without a word (as a misspelt ``@expext`` is).
"""

from __future__ import annotations

import json
from pathlib import Path
from xml.etree import ElementTree

import pytest
from click.testing import CliRunner, Result

from mintlang.cli import main
from tests.runtime.test_junit_report_is_valid import schema

_IGNORED = "is read only from the program, not from its configuration file: this one is ignored"


def _mint_test(*arguments: str | Path) -> Result:
    return CliRunner().invoke(main, ["test", "-j", "1", "--color", "never", *(str(argument) for argument in arguments)])


def _application(folder: Path, program: str, configuration: str) -> tuple[Path, Path]:
    (folder / "cell.mnt").write_text(program, encoding="utf-8")
    (folder / "cell.cfg").write_text(configuration, encoding="utf-8")
    return folder / "cell.mnt", folder / "cell.cfg"


def test_a_program_whose_only_expectations_are_in_its_configuration_is_a_test_in_error(tmp_path: Path) -> None:
    program, configuration = _application(tmp_path, "DIM a = 1\n", "RESETALL\nREM @expect a = 2\n")
    result = _mint_test(tmp_path)
    assert result.exit_code == 1
    assert result.stdout.splitlines()[0] == (
        f"ERROR  {program}  no expectation to check: add REM @expect lines or [[expect]] to its scenario"
    )
    assert result.stderr.splitlines() == [f"warning: {configuration}:2:5: @expect {_IGNORED}"]


@pytest.mark.parametrize(
    ("configuration", "warned"),
    [
        pytest.param("REM @sim drives enabled\n", ["1:5: @sim"], id="a-sim-line"),
        pytest.param("RESETALL : REM @expect a = 2\n", ["1:16: @expect"], id="after-a-statement"),
        pytest.param("REM @expext a = 2\n", ["1:5: @expext"], id="a-misspelt-one"),
        pytest.param("REM @author the cell's builder\nREM a = 2\n", [], id="plain-comments"),
    ],
)
def test_the_program_s_own_test_runs_and_each_directive_of_its_configuration_is_warned_of(
    tmp_path: Path, configuration: str, warned: list[str]
) -> None:
    _, path = _application(tmp_path, "DIM a = 1\nREM @expect a = 1\n", configuration)
    result = _mint_test(tmp_path)
    assert result.exit_code == 0 and result.stdout.startswith("PASSED ")
    assert result.stderr.splitlines() == [f"warning: {path}:{place} {_IGNORED}" for place in warned]


def test_a_configuration_shared_by_two_programs_is_warned_of_once(tmp_path: Path) -> None:
    (tmp_path / "pyproject.toml").write_text('[tool.mint]\nconfig = "line.cfg"\n', encoding="utf-8")
    (tmp_path / "line.cfg").write_text("REM @sim drives enabled\n", encoding="utf-8")
    for name in ("one.mnt", "two.mnt"):
        (tmp_path / name).write_text("DIM a = 1\nREM @expect a = 1\n", encoding="utf-8")
    result = _mint_test(tmp_path)
    assert result.stdout.splitlines()[2].startswith("2 passed in ")
    assert len(result.stderr.splitlines()) == 1 and result.stderr.endswith(f":1:5: @sim {_IGNORED}\n")


def test_quiet_says_nothing_more_as_mint_run_quiet_does(tmp_path: Path) -> None:
    _application(tmp_path, "DIM a = 1\nREM @expect a = 1\n", "REM @sim drives enabled\n")
    result = _mint_test(tmp_path, "--quiet")
    assert (result.exit_code, result.stdout, result.stderr) == (0, "", "")


def test_the_json_report_carries_them_with_the_test_as_mint_run_s_report_does(tmp_path: Path) -> None:
    _, configuration = _application(tmp_path, "DIM a = 1\nREM @expect a = 1\n", "REM @expect a = 2\n")
    (test,) = json.loads(_mint_test(tmp_path, "--format", "json").stdout)["tests"]
    assert test["verdict"] == "passed"
    assert test["ignored_directives"] == [f"{configuration}:1:5: @expect {_IGNORED}"]


def test_the_junit_report_carries_them_as_the_testcase_s_standard_error(tmp_path: Path) -> None:
    _, configuration = _application(tmp_path, "DIM a = 1\n", "REM @expect a = 2\n")
    report = _mint_test(tmp_path, "--format", "junit").stdout
    schema().validate(report)
    case = ElementTree.fromstring(report).find("testsuite/testcase")
    assert case is not None and case.find("error") is not None
    assert case.findtext("system-err") == f"warning: {configuration}:1:5: @expect {_IGNORED}\n"
