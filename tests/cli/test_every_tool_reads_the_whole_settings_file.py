"""A settings file is checked whole by every tool, as ruff checks its own whatever command runs (README,
Configuration: an unknown key stops the tool with exit status 2). A typo in ``[run]`` stopped ``mint-run``
only, so ``mint check`` in CI or a pre-commit hook passed a file that the next ``mint-run`` refused. A tool's
table is checked by its options' names and the kind of value each takes; what the value means (a scenario
file that is not there yet) is the tool's own business when it runs."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner, Result

from mintlang.cli import main, settings
from mintlang.settings.model import TOOL_TABLES
from tests.cli.invoking import write

# The README's example settings file (Configuration): every key is one of its tool's options.
README_EXAMPLE = """controller = "nextmove-bx"
select = ["E", "W"]
ignore = ["W111"]

[run]
until-ms = 5000
drives = "enabled"
stimulus = ["scenarios/start.toml"]

[migrate]
format = "json"

[format]
indent-width = 4
"""


def invoke(*arguments: str | Path) -> Result:
    return CliRunner().invoke(main, [str(argument) for argument in arguments])


@pytest.mark.parametrize(
    ("table", "problem"),
    [
        ("[run]\nuntl-ms = 3\n", "2:1: run.untl-ms: unknown key (known: "),
        ("[migrate]\nformt = 'json'\n", "2:1: migrate.formt: unknown key (known: "),
        ("[format]\nindnt-width = 4\n", "2:1: format.indnt-width: unknown key (known: "),
        ("[run]\nrealtime = 1\n", "2:12: run.realtime: must be true or false"),
        ("[migrate]\nexclude = ['old']\n", "2:1: migrate.exclude: a setting of every tool: write it beside select"),
    ],
)
def test_mint_check_stops_at_a_bad_key_of_another_tools_table(tmp_path: Path, table: str, problem: str) -> None:
    settings = write(tmp_path / "mint.toml", table)
    result = invoke("check", write(tmp_path / "cell.mnt", "PRINT 1\n"))
    assert (result.exit_code, result.stdout) == (2, "")
    [printed] = result.stderr.splitlines()
    assert printed.startswith(f"mint check: {settings.absolute()}:{problem}")


@pytest.mark.parametrize(
    ("tool", "table", "problem"),
    [
        ("format", "[run]\nuntl-ms = 3\n", "mint format: {settings}:2:1: run.untl-ms: unknown key"),
        ("run", "[format]\nindnt-width = 4\n", "mint-run: {settings}:2:1: format.indnt-width: unknown key"),
        ("migrate", "[run]\nuntl-ms = 3\n", "mint-migrate: {settings}:2:1: run.untl-ms: unknown key"),
    ],
)
def test_each_tool_stops_at_a_bad_key_of_another_tools_table(
    tmp_path: Path, tool: str, table: str, problem: str
) -> None:
    settings = write(tmp_path / "mint.toml", table)
    result = invoke(tool, write(tmp_path / "cell.mnt", "PRINT 1\nEND\n"))
    assert result.exit_code == 2
    assert result.stderr.startswith(problem.format(settings=settings.absolute()))


def test_the_readme_example_is_a_good_settings_file_for_mint_check(tmp_path: Path) -> None:
    write(tmp_path / "mint.toml", README_EXAMPLE)  # its scenario file is not written: mint-run would say so
    result = invoke("check", write(tmp_path / "cell.mnt", "PRINT 1\n"))
    assert (result.exit_code, result.stderr) == (0, "")


def test_mint_test_reports_it_as_an_error_of_each_test(tmp_path: Path) -> None:
    """As it reports a settings file that cannot be used (README, Configuration), and runs no test under it."""
    settings = write(tmp_path / "mint.toml", "[run]\nuntl-ms = 3\n")
    write(tmp_path / "cell.mnt", "REM @expect a = 2\nDIM a\na = 1 + 1\n")
    result = invoke("test", "-j", "1", tmp_path)
    assert result.exit_code == 1
    assert f"ERROR  {tmp_path / 'cell.mnt'}  {settings.absolute()}:2:1: run.untl-ms: unknown key" in result.stdout


def test_show_settings_stops_at_it_as_the_check_does(tmp_path: Path) -> None:
    settings = write(tmp_path / "mint.toml", "[run]\nuntl-ms = 3\n")
    result = invoke("check", "--show-settings", write(tmp_path / "cell.mnt", "PRINT 1\n"))
    assert (result.exit_code, result.stdout) == (2, "")
    assert result.stderr.startswith(f"mint check: {settings.absolute()}:2:1: run.untl-ms: unknown key")


def test_every_tools_table_is_checked_by_its_commands_options() -> None:
    # a table the settings know (TOOL_TABLES) with no command to check it by would pass unchecked
    assert set(settings._COMMANDS) == set(TOOL_TABLES)
