"""``mint check --fix``, ``--unsafe-fixes`` and ``--diff``; fixes in the JSON and SARIF reports."""

from __future__ import annotations

import json
import os
import stat
import subprocess
import sys
from importlib.metadata import version
from pathlib import Path

import pytest
from click.testing import CliRunner, Result

from mintlang.cli import main

# Line 1: typographic quotes (W101, a safe fix). Line 3: IDL for IDLE (E3007, an unsafe respelling).
PROGRAM = "PRINT “ready”\nDIM a\na = 1\nPAUSE IDL.0\nPRINT a\n"
SAFELY_FIXED = 'PRINT "ready"\nDIM a\na = 1\nPAUSE IDL.0\nPRINT a\n'
ALL_FIXED = 'PRINT "ready"\nDIM a\na = 1\nPAUSE IDLE.0\nPRINT a\n'


def mint_check(*arguments: str | Path) -> Result:
    return CliRunner().invoke(main, ["check", *(str(argument) for argument in arguments)])


def program(tmp_path: Path, text: str = PROGRAM, name: str = "cell.mnt") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def test_fix_writes_the_safe_fixes_and_reports_what_is_left(tmp_path: Path) -> None:
    path = program(tmp_path)
    result = mint_check("--fix", path)
    assert path.read_text(encoding="utf-8") == SAFELY_FIXED
    assert result.exit_code == 1  # the E3007 is left, an error
    assert "error[E3007]" in result.stdout and "W101" not in result.stdout.split("checked:")[0]
    assert "Fixed 1 finding in 1 file (1 W101)." in result.stdout
    assert "1 finding fixable with --fix --unsafe-fixes." in result.stdout


def test_unsafe_fixes_apply_the_guesses_too_and_exit_0_when_nothing_is_left(tmp_path: Path) -> None:
    path = program(tmp_path)
    result = mint_check("--fix", "--unsafe-fixes", path)
    assert path.read_text(encoding="utf-8") == ALL_FIXED
    assert result.exit_code == 0
    assert "Fixed 2 findings in 1 file (1 E3007, 1 W101)." in result.stdout


def test_without_fix_the_report_says_what_fix_would_do(tmp_path: Path) -> None:
    path = program(tmp_path)
    result = mint_check(path)
    assert path.read_text(encoding="utf-8") == PROGRAM
    assert "1 finding fixable with --fix (1 more with --unsafe-fixes)." in result.stdout


def test_diff_shows_the_change_and_writes_nothing(tmp_path: Path) -> None:
    path = program(tmp_path)
    result = mint_check("--diff", path)
    assert path.read_text(encoding="utf-8") == PROGRAM
    assert result.exit_code == 1  # there is something to fix
    assert result.stdout == (
        f'--- {path}\n+++ {path}\n@@ -1,4 +1,4 @@\n-PRINT “ready”\n+PRINT "ready"\n DIM a\n a = 1\n PAUSE IDL.0\n'
    )
    assert "mint check: Would fix 1 finding in 1 file (1 W101)." in result.stderr


def test_diff_with_nothing_to_fix_exits_0(tmp_path: Path) -> None:
    result = mint_check("--diff", program(tmp_path, SAFELY_FIXED))
    assert (result.exit_code, result.stdout) == (0, "")


def test_the_file_keeps_its_encoding_and_line_ends(tmp_path: Path) -> None:
    path = tmp_path / "crlf.mnt"
    path.write_bytes("PRINT “x”\r\nREM café\r\n".encode("cp1252"))
    assert mint_check("--fix", path).exit_code == 0
    assert path.read_bytes() == 'PRINT "x"\r\nREM café\r\n'.encode("cp1252")


@pytest.mark.skipif(not hasattr(os, "geteuid"), reason="POSIX permissions")
def test_a_read_only_file_is_not_fixed_and_says_so(tmp_path: Path) -> None:
    path = program(tmp_path)
    path.chmod(stat.S_IRUSR)
    result = mint_check("--fix", path)
    assert result.exit_code == 2
    assert f"mint check: cannot write {path}: the file is read-only; not fixed" in result.stderr
    assert path.read_text(encoding="utf-8") == PROGRAM
    assert "warning[W101]" in result.stdout  # the finding stays reported: the file still holds it
    assert "\nNothing fixed: 1 file with fixes could not be written.\n" in result.stdout
    assert "Nothing to fix" not in result.stdout


def test_standard_input_is_shown_fixed_not_written(tmp_path: Path) -> None:
    runner = CliRunner()
    refused = runner.invoke(main, ["check", "--fix", "-"], input=PROGRAM)
    assert refused.exit_code == 2 and "use --diff" in refused.stderr
    shown = runner.invoke(main, ["check", "--diff", "--stdin-filename", "cell.mnt", "-"], input=PROGRAM)
    assert shown.exit_code == 1 and '+PRINT "ready"' in shown.stdout


def test_json_carries_each_fix_with_its_safety_and_edits(tmp_path: Path) -> None:
    records = json.loads(mint_check("--format", "json", program(tmp_path)).stdout)
    quotes, respelling = records
    assert quotes["fixes"] == [
        {
            "title": "Replace with plain quotes",
            "safe": True,
            "edits": [
                {"line": 1, "column": 7, "end_line": 1, "end_column": 8, "text": '"'},
                {"line": 1, "column": 13, "end_line": 1, "end_column": 14, "text": '"'},
            ],
        }
    ]
    assert respelling["fixes"] == [
        {
            "title": "Replace with IDLE",
            "safe": False,
            "edits": [{"line": 4, "column": 7, "end_line": 4, "end_column": 10, "text": "IDLE"}],
        }
    ]


def test_sarif_names_the_tool_version_and_carries_fixes(tmp_path: Path) -> None:
    path = program(tmp_path)
    document = json.loads(mint_check("--format", "sarif", path).stdout)
    run = document["runs"][0]
    assert run["tool"]["driver"]["version"] == version("mintlang")
    assert {rule["id"] for rule in run["tool"]["driver"]["rules"]} == {"W101", "E3007"}
    respelling = next(result for result in run["results"] if result["ruleId"] == "E3007")
    assert respelling["fixes"] == [
        {
            "description": {"text": "Replace with IDLE"},
            "artifactChanges": [
                {
                    "artifactLocation": {"uri": str(path)},
                    "replacements": [
                        {
                            "deletedRegion": {"startLine": 4, "startColumn": 7, "endLine": 4, "endColumn": 10},
                            "insertedContent": {"text": "IDLE"},
                        }
                    ],
                }
            ],
            "properties": {"safe": False},
        }
    ]


def test_the_installed_command_fixes_files_in_a_directory(tmp_path: Path) -> None:
    first, second = program(tmp_path, name="a.mnt"), program(tmp_path, name="b.mnt")
    mint = Path(sys.executable).with_name("mint")
    run = subprocess.run(
        [mint, "check", "--fix", "-j", "2", str(tmp_path)], capture_output=True, text=True, check=False
    )
    assert run.returncode == 1, run.stderr
    assert first.read_text(encoding="utf-8") == second.read_text(encoding="utf-8") == SAFELY_FIXED
    assert "Fixed 2 findings in 2 files (2 W101)." in run.stdout
