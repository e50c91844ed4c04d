"""``mint rule``: one code, several, or all of them, as Markdown text or JSON."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

from click.testing import CliRunner, Result

from mintlang.cli import main
from mintlang.ruledocs import rules


def mint_rule(*arguments: str) -> Result:
    return CliRunner().invoke(main, ["rule", *arguments])


def test_a_code_is_explained_with_its_example_fix_and_sections() -> None:
    result = mint_rule("E2016")
    assert result.exit_code == 0
    page = result.stdout
    assert page.startswith("# E2016: Invalid index\n")
    for heading in ("## What it catches", "## Why it matters", "## Example", "## Fix", "## In the manual"):
        assert heading in page
    assert "DIM speeds(100)\nspeeds(101) = 2000" in page  # the index 101 is past the array (12.4, #2016)
    assert "- Mint v4 guide §12.4 Mint Error Codes and Messages" in page
    assert "- Mint v4 guide §3.3 Arrays" in page


def test_the_short_and_the_four_digit_spelling_name_the_same_error() -> None:
    short, full = mint_rule("e2"), mint_rule("E0002")
    assert short.exit_code == full.exit_code == 0 and short.stdout == full.stdout
    assert "Axis specified out of range" in short.stdout.splitlines()[0]


def test_a_safe_fix_says_so() -> None:
    assert "Safe: `mint check --fix` applies it" in mint_rule("W101").stdout
    assert "Unsafe:" in mint_rule("E3001").stdout
    assert "No automatic fix." in mint_rule("E2004").stdout


def test_all_lists_every_documented_code_once() -> None:
    result = mint_rule("--all")
    titles = [line for line in result.stdout.splitlines() if line.startswith("# ")]
    assert [title.split(":")[0][2:] for title in titles] == [rule.code for rule in rules()]


def test_json_is_one_record_for_one_code_and_a_list_for_all() -> None:
    one = json.loads(mint_rule("W103", "--format", "json").stdout)
    assert one["code"] == "W103" and one["severity"] == "warning" and one["group"] == "Names"
    assert one["fix"]["safety"] == "none" and one["example"]["before"].startswith("DIM spare")
    assert one["manual"] == ["Mint v4 guide §3.2.5 Variables", "Mint v4 guide §3.9 Mint Interpreter Limitations"]
    every = json.loads(mint_rule("--all", "--format", "json").stdout)
    assert [record["code"] for record in every] == [rule.code for rule in rules()]


def test_an_unknown_code_is_one_line_with_the_code_it_resembles() -> None:
    result = mint_rule("W13")
    assert result.exit_code == 2
    assert result.stderr == "mint rule: 'W13' is not a code the checker reports (did you mean 'W113'?)\n"


def test_no_code_is_a_usage_error() -> None:
    result = mint_rule()
    assert result.exit_code == 2 and "name a code" in result.stderr


def test_the_installed_command_prints_markdown_when_not_on_a_terminal(tmp_path: Path) -> None:
    mint = Path(sys.executable).with_name("mint")
    run = subprocess.run([mint, "rule", "I201"], capture_output=True, text=True, check=False)
    assert run.returncode == 0
    assert "```mint\nDIM b\nb = POS[1]\nPRINT b\n```" in run.stdout
