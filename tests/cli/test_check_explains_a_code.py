"""``mint check --explain CODE`` prints the code's page, as ``mint rule CODE`` does, and checks nothing.

A ruff user asks the linter itself what a code means; the page is the one ``mint rule`` prints (its
title is the guide's name of the error: #2010 "RETURN w/o GOSUB", 000:18965), and no path is needed.
"""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from mintlang.cli import main
from tests.cli.invoking import mint_check, write


def test_explain_prints_the_page_mint_rule_prints_without_a_path() -> None:
    explained = mint_check("--explain", "E2010")
    assert explained.exit_code == 0
    assert explained.stdout.splitlines()[0] == "# E2010: RETURN w/o GOSUB"
    assert explained.stdout == CliRunner().invoke(main, ["rule", "E2010"]).stdout


def test_explain_takes_the_manuals_short_spelling() -> None:
    assert mint_check("--explain", "E17").stdout.splitlines()[0].startswith("# E0017: ")


def test_explain_checks_no_file_it_is_given(tmp_path: Path) -> None:
    program = write(tmp_path / "p.mnt", "PRINT 1\nRETURN\n")
    explained = mint_check("--explain", "W103", program)
    assert explained.exit_code == 0
    assert explained.stdout.startswith("# W103: ")
    assert "p.mnt" not in explained.stdout


def test_an_unknown_code_is_a_usage_error_with_a_suggestion() -> None:
    explained = mint_check("--explain", "2010")
    assert explained.exit_code == 2
    assert "did you mean 'E2010'?" in explained.stderr


def test_an_unknown_code_is_said_by_the_command_the_user_ran() -> None:
    assert mint_check("--explain", "2010").stderr.startswith("mint check: '2010' is not a code")
    assert CliRunner().invoke(main, ["rule", "2010"]).stderr.startswith("mint rule: '2010' is not a code")
