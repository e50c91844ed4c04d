"""A path ``mint check`` could not check is a finding (W120) of the json, sarif and github reports, as ruff
reports a file it cannot read as E902; it is still said on standard error, and the check still exits with 2.

The text report is unchanged: its closing count says how many files were checked, and the line on
standard error says which was not. ``--select``/``--ignore`` leave W120 out as ruff's selection leaves E902
out (the line on standard error and exit 2 stay); a suppression comment never reaches it.
"""

from __future__ import annotations

import errno
import json
import os
from pathlib import Path

import pytest

from tests.cli.invoking import mint_check, write

CLEAN = "DIM a\na = 1\nPRINT a\n"  # no finding: every report entry below is the path not checked


def _entry(path: Path, message: str, line: int = 1, column: int = 1) -> dict[str, object]:
    return {
        "path": str(path),
        "code": "W120",
        "mint_error": None,
        "severity": "warning",
        "message": message,
        "line": line,
        "column": column,
        "end_line": line,
        "end_column": column,
        "fixes": [],
    }


def test_a_missing_path_is_an_entry_at_1_1_beside_its_line_on_standard_error(tmp_path: Path) -> None:
    missing = tmp_path / "missing.mnt"
    result = mint_check("--format", "json", write(tmp_path / "ok.mnt", CLEAN), missing)
    assert result.exit_code == 2
    assert json.loads(result.stdout) == [_entry(missing, "No such file or directory")]
    assert result.stderr == f"mint check: no such file or directory: {missing}\n"


def test_a_missing_path_alone_still_writes_a_json_report(tmp_path: Path) -> None:
    missing = tmp_path / "missing.mnt"
    result = mint_check("--format", "json", missing)
    assert (result.exit_code, json.loads(result.stdout)) == (2, [_entry(missing, "No such file or directory")])


def test_a_file_that_is_not_text_is_placed_at_its_nul_byte(tmp_path: Path) -> None:
    binary = tmp_path / "blob.mnt"
    binary.write_bytes(b"PRINT 1\nPR\x00INT 2\n")  # line 2: P, R, then the NUL byte in column 3
    result = mint_check("--format", "json", binary)
    assert result.exit_code == 2
    assert json.loads(result.stdout) == [_entry(binary, "not Mint text (a NUL byte)", 2, 3)]
    assert result.stderr == f"mint check: {binary}:2:3: not Mint text (a NUL byte): not checked\n"


def test_a_link_loop_found_in_a_directory_is_an_entry_with_the_systems_reason(tmp_path: Path) -> None:
    loop = tmp_path / "line" / "loop.mnt"
    loop.parent.mkdir()
    loop.symlink_to(loop.name)
    result = mint_check("--format", "json", loop.parent)
    assert result.exit_code == 2
    assert json.loads(result.stdout) == [_entry(loop, os.strerror(errno.ELOOP))]


@pytest.mark.skipif(os.name != "posix" or os.geteuid() == 0, reason="a superuser lists any directory")
def test_a_directory_that_cannot_be_listed_is_an_entry(tmp_path: Path) -> None:
    locked = tmp_path / "locked"
    write(locked / "p.mnt", CLEAN)
    locked.chmod(0)
    try:
        result = mint_check("--format", "json", locked)
    finally:
        locked.chmod(0o755)
    assert result.exit_code == 2
    assert json.loads(result.stdout) == [_entry(locked, os.strerror(errno.EACCES))]


def test_a_program_whose_configuration_cannot_be_read_is_an_entry_after_the_configuration(tmp_path: Path) -> None:
    configuration = tmp_path / "cell.cfg"
    configuration.write_bytes(b"\x00")
    program = write(tmp_path / "cell.mnt", CLEAN)
    result = mint_check("--format", "json", program)
    assert result.exit_code == 2
    assert json.loads(result.stdout) == [
        _entry(configuration, "not Mint text (a NUL byte)"),
        _entry(program, f"not checked, as its configuration file {configuration} could not be read"),
    ]


def test_sarif_gives_the_rule_its_page_and_the_region_of_the_nul_byte(tmp_path: Path) -> None:
    binary = tmp_path / "blob.mnt"
    binary.write_bytes(b"\n\n   \x00")
    result = mint_check("--format", "sarif", binary)
    assert result.exit_code == 2
    run = json.loads(result.stdout)["runs"][0]
    [rule] = run["tool"]["driver"]["rules"]
    assert rule["id"] == "W120" and rule["shortDescription"] == {"text": "File not checked"}
    assert "fullDescription" in rule
    [finding] = run["results"]
    assert (finding["ruleId"], finding["level"], finding["message"]) == (
        "W120",
        "warning",
        {"text": "not Mint text (a NUL byte)"},
    )
    region = {"startLine": 3, "startColumn": 4, "endLine": 3, "endColumn": 4}
    assert finding["locations"][0]["physicalLocation"] == {"artifactLocation": {"uri": str(binary)}, "region": region}


def test_github_annotates_the_path(tmp_path: Path) -> None:
    missing = tmp_path / "missing.mnt"
    result = mint_check("--format", "github", missing)
    assert result.exit_code == 2
    properties = f"file={missing},line=1,col=1,endLine=1,endColumn=1,title=W120".replace(":", "%3A")
    assert result.stdout == f"::warning {properties}::No such file or directory\n"


def test_statistics_in_json_count_the_paths_not_checked(tmp_path: Path) -> None:
    result = mint_check("--format", "json", "--statistics", tmp_path / "a.mnt", tmp_path / "b.mnt")
    assert result.exit_code == 2
    assert json.loads(result.stdout) == [{"code": "W120", "count": 2, "title": "File not checked"}]


def test_the_text_report_is_unchanged(tmp_path: Path) -> None:
    missing = tmp_path / "missing.mnt"
    result = mint_check(write(tmp_path / "ok.mnt", CLEAN), missing)
    assert result.exit_code == 2
    assert result.stdout == "1 file checked: 0 errors, 0 warnings, 0 infos\n"
    assert result.stderr == f"mint check: no such file or directory: {missing}\n"


@pytest.mark.parametrize("selection", [("--ignore", "W120"), ("--ignore", "W1"), ("--select", "E")])
def test_a_selection_without_w120_leaves_it_to_standard_error_and_the_exit_status(
    tmp_path: Path, selection: tuple[str, str]
) -> None:
    missing = tmp_path / "missing.mnt"
    result = mint_check("--format", "json", *selection, write(tmp_path / "ok.mnt", CLEAN), missing)
    assert result.exit_code == 2
    assert json.loads(result.stdout) == []
    assert result.stderr == f"mint check: no such file or directory: {missing}\n"


def test_selecting_it_alone_reports_it(tmp_path: Path) -> None:
    missing = tmp_path / "missing.mnt"
    result = mint_check("--format", "json", "--select", "W120", missing)
    assert json.loads(result.stdout) == [_entry(missing, "No such file or directory")]


def test_a_suppression_comment_in_a_file_not_read_as_a_program_does_not_hide_it(tmp_path: Path) -> None:
    binary = tmp_path / "blob.mnt"
    binary.write_bytes(b"REM mint: ignore-file[W120]\n\x00\n")
    result = mint_check("--format", "json", binary)
    assert json.loads(result.stdout) == [_entry(binary, "not Mint text (a NUL byte)", 2, 1)]
