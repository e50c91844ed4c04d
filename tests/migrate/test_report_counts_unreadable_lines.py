"""The report counts unreadable lines, not errors, and lists them in line order.

A line the v3 reader cannot read may hold two errors: ``café = 5`` has a character no v3
name has and, before it, a word that is no keyword. The table and the totals said "3
unreadable lines" for a program of two lines, and listed line 1, line 2, then line 1 again
(the errors of reading the characters first, then those of reading the words).
"""

from __future__ import annotations

import json
from pathlib import Path

from click.testing import CliRunner

from mintlang.migrate.cli import migrate as command

SOURCE = "caf\u00e9 = 5\nPRINT 2 @\n"  # line 1: two errors; line 2: a character no v3 line has


def _run(tmp_path: Path, *arguments: str) -> str:
    path = tmp_path / "two.mnt"
    path.write_text(SOURCE, encoding="utf-8")
    return CliRunner().invoke(command, [*arguments, "--color", "never", str(path)]).output


def test_the_text_report_counts_each_unreadable_line_once(tmp_path: Path) -> None:
    output = _run(tmp_path)
    assert "2 unreadable lines" in output and "3 unreadable lines" not in output
    row = next(line for line in output.splitlines() if "│ program │" in line)
    assert row.split("│")[-1].strip() == "2"


def test_unreadable_lines_are_listed_in_line_order(tmp_path: Path) -> None:
    listed = [
        line.split("unreadable v3 line ")[1].split(":")[0]
        for line in _run(tmp_path).splitlines()
        if "unreadable v3" in line
    ]
    assert listed == ["1", "1", "2"]
    errors = json.loads(_run(tmp_path, "--format", "json"))["files"][0]["errors"]
    assert [error.split(":")[0] for error in errors] == ["line 1", "line 1", "line 2"]


def test_a_line_flagged_as_invalid_in_v3_is_counted_unreadable(tmp_path: Path) -> None:
    """``MOVEA =`` reads as an assignment but has no value: error 2005, No expression (000:18930-18934),
    which the v3 check finds after the grammar. X-COMMENTED flagged it; the counts left it out."""
    path = tmp_path / "empty.mnt"
    path.write_text("DIM a(2)\nMOVEA =\nPRINT a(1)\nSTOP\n")
    result = CliRunner().invoke(command, ["--format", "json", str(path)])
    row = json.loads(result.stdout)["files"][0]
    flagged = [item["original_line"] for item in row["manual"] if item["rule"] == "X-COMMENTED"]
    assert flagged == [2]
    assert row["errors"] == ["line 2: E2005 No expression: MOVEA is given no value after '='"]
    text = CliRunner().invoke(command, ["--color", "never", str(path)]).output
    assert "empty.mnt: unreadable v3 line 2: E2005 No expression" in text
    assert text.rstrip().endswith("1 unreadable line")
