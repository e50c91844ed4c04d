"""With nothing to check, a machine-readable report is still written, empty: a tool reading it gets a
document it can parse (JSON ``[]``, a SARIF run without results, no GitHub annotation). The text report
stays a one-line message on standard error; every format still exits with 2 and says why there.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.cli.invoking import mint_check, write


def _empty_folder(tmp_path: Path) -> Path:
    write(tmp_path / "project" / "notes.txt", "PRINT b\n")  # a folder holding no .mnt file
    return tmp_path / "project"


def test_a_json_report_of_a_folder_without_programs_is_an_empty_list(tmp_path: Path) -> None:
    folder = _empty_folder(tmp_path)
    result = mint_check("--format", "json", folder)
    assert (result.exit_code, json.loads(result.stdout)) == (2, [])
    assert result.stderr == f"mint check: no .mnt files found in {folder}\n"


def test_json_statistics_of_nothing_are_an_empty_list(tmp_path: Path) -> None:
    result = mint_check("--format", "json", "--statistics", _empty_folder(tmp_path))
    assert (result.exit_code, json.loads(result.stdout)) == (2, [])


def test_a_sarif_report_of_nothing_is_one_run_without_results_or_rules(tmp_path: Path) -> None:
    result = mint_check("--format", "sarif", _empty_folder(tmp_path))
    assert result.exit_code == 2
    document = json.loads(result.stdout)
    assert document["version"] == "2.1.0"
    [run] = document["runs"]
    assert (run["results"], run["tool"]["driver"]["rules"]) == ([], [])


@pytest.mark.parametrize("output_format", ["text", "github"])
def test_text_and_github_write_nothing_on_standard_output(tmp_path: Path, output_format: str) -> None:
    folder = _empty_folder(tmp_path)
    result = mint_check("--format", output_format, folder)
    assert (result.exit_code, result.stdout) == (2, "")
    assert result.stderr == f"mint check: no .mnt files found in {folder}\n"


def test_the_empty_report_goes_to_the_output_file(tmp_path: Path) -> None:
    report = tmp_path / "report.json"
    result = mint_check("--format", "json", "--output-file", report, _empty_folder(tmp_path))
    assert (result.exit_code, result.stdout) == (2, "")
    assert json.loads(report.read_text(encoding="utf-8")) == []


def test_a_path_not_checked_whose_finding_is_ignored_leaves_an_empty_json_report(tmp_path: Path) -> None:
    missing = tmp_path / "missing.mnt"
    result = mint_check("--format", "json", "--ignore", "W120", missing)
    assert (result.exit_code, json.loads(result.stdout)) == (2, [])
    assert result.stderr == f"mint check: no such file or directory: {missing}\n"
