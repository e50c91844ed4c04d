"""``mint check`` on the command line: exit status, output formats, options, file discovery."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest
from click.testing import CliRunner, Result

from mintlang.cli import main

CLEAN = "DIM a\na = 1\nPRINT a\n"
UNDECLARED = "DIM a\na = 1\nPRINT b\n"  # b: E3001 on line 3, columns 7 to 8


def mint_check(*arguments: str | Path) -> Result:
    return CliRunner().invoke(main, ["check", *(str(argument) for argument in arguments)])


def write(directory: Path, name: str, text: str) -> Path:
    path = directory / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


def json_records(*arguments: str | Path) -> list[dict]:
    result = mint_check("--format", "json", *arguments)
    assert result.exit_code in (0, 1), result.output
    return json.loads(result.stdout)


# ----------------------------------------------------------------- exit status


def test_a_clean_file_exits_with_0(tmp_path: Path) -> None:
    result = mint_check(write(tmp_path, "clean.mnt", CLEAN))
    assert result.exit_code == 0
    assert "1 file checked: 0 errors, 0 warnings, 0 infos" in result.stdout


def test_a_file_with_an_error_exits_with_1(tmp_path: Path) -> None:
    result = mint_check(write(tmp_path, "bad.mnt", UNDECLARED))
    assert result.exit_code == 1
    assert "error[E3001]" in result.stdout
    assert "bad.mnt:3:7" in result.stdout


def test_warnings_alone_exit_with_0(tmp_path: Path) -> None:
    result = mint_check(write(tmp_path, "warn.mnt", "DIM spare\n"))
    assert result.exit_code == 0
    assert "warning[W103]" in result.stdout


def test_a_missing_path_exits_with_2_and_a_one_line_message(tmp_path: Path) -> None:
    missing = tmp_path / "missing.mnt"
    result = mint_check(missing)
    assert result.exit_code == 2
    assert result.stderr.strip() == f"mint check: no such file or directory: {missing}"
    assert result.stdout == ""
    assert "Traceback" not in result.output


def test_a_directory_without_mint_files_exits_with_2(tmp_path: Path) -> None:
    write(tmp_path, "notes.txt", "PRINT b\n")
    result = mint_check(tmp_path)
    assert result.exit_code == 2
    assert result.stderr.startswith("mint check: no .mnt files found in ")
    assert "Traceback" not in result.output


def test_an_unknown_controller_is_a_usage_error(tmp_path: Path) -> None:
    result = mint_check("--controller", "nextmove-xyz", write(tmp_path, "clean.mnt", CLEAN))
    assert result.exit_code == 2


# --------------------------------------------------------------------- formats


def test_json_output_is_one_array_of_records_with_one_based_positions(tmp_path: Path) -> None:
    path = write(tmp_path, "bad.mnt", UNDECLARED)
    assert json_records(path) == [
        {
            "path": str(path),
            "code": "E3001",
            "mint_error": 3001,
            "severity": "error",
            "message": "Variable undefined, use DIM: 'b' is not declared",
            "line": 3,
            "column": 7,
            "end_line": 3,
            "end_column": 8,
            "fixes": [  # a DIM beside the file's other DIM, before line 2: a guess, so not safe
                {
                    "title": "Declare 'b' with DIM",
                    "safe": False,
                    "edits": [{"line": 2, "column": 1, "end_line": 2, "end_column": 1, "text": "DIM b\n"}],
                }
            ],
        }
    ]


def test_json_records_have_exactly_the_documented_keys(tmp_path: Path) -> None:
    path = write(tmp_path, "several.mnt", "DIM spare\nSPEED\nPRINT q\n")
    records = json_records(path)
    assert [record["code"] for record in records] == ["W103", "E2005", "E3001"]
    keys = {"path", "code", "mint_error", "severity", "message", "line", "column", "end_line", "end_column", "fixes"}
    assert all(set(record) == keys for record in records)
    assert [record["mint_error"] for record in records] == [None, 2005, 3001]


def test_json_output_of_a_clean_file_is_an_empty_array(tmp_path: Path) -> None:
    assert json_records(write(tmp_path, "clean.mnt", CLEAN)) == []


def test_json_end_positions_are_exclusive_and_count_characters(tmp_path: Path) -> None:
    path = write(tmp_path, "wide.mnt", 'PRINT "é"\r\nDIM a\r\nPRINT a, undeclared\r\n')
    (record,) = json_records(path)
    assert (record["line"], record["column"], record["end_line"], record["end_column"]) == (3, 10, 3, 20)


def test_sarif_output_is_sarif_2_1_0(tmp_path: Path) -> None:
    path = write(tmp_path, "bad.mnt", UNDECLARED)
    result = mint_check("--format", "sarif", path)
    assert result.exit_code == 1
    document = json.loads(result.stdout)
    assert document["version"] == "2.1.0"
    (run,) = document["runs"]
    (rule,) = run["tool"]["driver"]["rules"]
    assert (rule["id"], rule["shortDescription"]) == ("E3001", {"text": "Variable undefined, use DIM"})
    assert rule["helpUri"].endswith("/E3001.md")
    (finding,) = run["results"]
    assert finding["ruleId"] == "E3001"
    assert finding["level"] == "error"
    (location,) = finding["locations"]
    assert location["physicalLocation"]["artifactLocation"]["uri"] == str(path)
    assert location["physicalLocation"]["region"] == {"startLine": 3, "startColumn": 7, "endLine": 3, "endColumn": 8}


@pytest.mark.parametrize(
    ("name", "uri"),
    [
        pytest.param("my cell.mnt", "my%20cell.mnt", id="a space"),
        pytest.param("50%.mnt", "50%25.mnt", id="a percent sign"),
        pytest.param("café.mnt", "caf%C3%A9.mnt", id="a letter beyond ASCII, in UTF-8"),
        pytest.param("line 2/a.mnt", "line%202/a.mnt", id="a folder, its slash kept"),
    ],
)
def test_sarif_names_each_file_by_a_valid_uri_reference(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, name: str, uri: str
) -> None:
    monkeypatch.chdir(tmp_path)
    write(tmp_path, name, "DIM spare\nPRINT “x”\n")  # W103, and W101 with its fix
    document = json.loads(mint_check("--format", "sarif", name).stdout)
    (spare, quotes) = document["runs"][0]["results"]
    assert spare["locations"][0]["physicalLocation"]["artifactLocation"]["uri"] == uri
    assert quotes["fixes"][0]["artifactChanges"][0]["artifactLocation"]["uri"] == uri


def test_sarif_levels_for_warnings_and_hints(tmp_path: Path) -> None:
    path = write(tmp_path, "soft.mnt", "DIM spare\nDIM b\nb = POS[1]\n")
    document = json.loads(mint_check("--format", "sarif", "--select", "W,I", path).stdout)
    assert [(r["ruleId"], r["level"]) for r in document["runs"][0]["results"]] == [
        ("W103", "warning"),
        ("I201", "note"),
    ]


def test_github_output_is_one_workflow_command_per_diagnostic(tmp_path: Path) -> None:
    path = write(tmp_path, "bad.mnt", "DIM spare\nPRINT b\n")
    result = mint_check("--format", "github", path)
    assert result.exit_code == 1
    lines = result.stdout.splitlines()
    assert lines == [
        f"::warning file={path},line=1,col=5,endLine=1,endColumn=10,title=W103::"
        "variable 'spare' is declared but never used",
        f"::error file={path},line=2,col=7,endLine=2,endColumn=8,title=E3001::"
        "Variable undefined, use DIM: 'b' is not declared",
    ]


# --------------------------------------------------------------------- options


def test_select_keeps_only_the_selected_codes(tmp_path: Path) -> None:
    path = write(tmp_path, "mixed.mnt", "DIM spare\nSPEED\nPRINT q\n")
    assert [r["code"] for r in json_records("--select", "E3001", path)] == ["E3001"]
    assert [r["code"] for r in json_records("--select", "W,E2005", path)] == ["W103", "E2005"]


def test_select_decides_the_exit_status(tmp_path: Path) -> None:
    path = write(tmp_path, "mixed.mnt", "DIM spare\nPRINT q\n")
    assert mint_check("--select", "W", path).exit_code == 0
    assert mint_check("--select", "e3001", path).exit_code == 1


def test_ignore_drops_a_prefix_of_codes(tmp_path: Path) -> None:
    path = write(tmp_path, "mixed.mnt", "DIM spare\nSPEED\nPRINT q\n")
    assert [r["code"] for r in json_records("--ignore", "W", path)] == ["E2005", "E3001"]
    assert [r["code"] for r in json_records("--ignore", "E3001,W103", path)] == ["E2005"]


def test_the_controller_changes_the_results(tmp_path: Path) -> None:
    # axis 8 exists on NextMove PCI (0 to 11) but not on NextMove BX (0 to 7)
    path = write(tmp_path, "axis.mnt", "SPEED.8 = 1\n")
    assert mint_check(path).exit_code == 0
    result = mint_check("--controller", "nextmove-bx", "--format", "json", path)
    assert result.exit_code == 1
    assert [(r["code"], r["line"]) for r in json.loads(result.stdout)] == [("E0002", 1)]


def test_the_controller_changes_the_message_of_speed_12(tmp_path: Path) -> None:
    path = write(tmp_path, "axis.mnt", "SPEED.12 = 1\n")
    (record,) = json_records("--controller", "nextmove-bx", path)
    assert record["code"] == "E0002"
    assert "NextMove BX" in record["message"]


def test_the_dialect_option_reads_mint_v3(tmp_path: Path) -> None:
    path = write(tmp_path, "old.mnt", "HMSPEED = 10\n")
    assert [r["code"] for r in json_records(path)] == ["E3001"]
    assert json_records("--dialect", "v3", path) == []


def test_config_makes_its_variables_visible_to_the_program(tmp_path: Path) -> None:
    program = write(tmp_path, "main.mnt", "PRINT jobCount\n")
    config = write(tmp_path, "setup.cfg", "DIM jobCount = 1\n")
    assert mint_check(program).exit_code == 1
    result = mint_check("--config", config, "--format", "json", program)
    assert result.exit_code == 0
    assert [(r["path"], r["code"]) for r in json.loads(result.stdout) if r["path"] == str(program)] == []


def test_a_configuration_name_any_program_uses_is_not_unused(tmp_path: Path) -> None:
    config = write(tmp_path, "setup.cfg", "DEFINE fast = 100\nDIM jobCount = 1\nDIM spare\n")
    uses = write(tmp_path, "uses.mnt", "SPEED = fast\nPRINT jobCount\n")
    other = write(tmp_path, "other.mnt", CLEAN)
    records = json_records("--config", config, uses, other)
    assert [(r["code"], r["line"]) for r in records if r["path"] == str(config)] == [("W103", 3)]


def test_a_configuration_named_as_config_and_as_a_path_is_reported_once(tmp_path: Path) -> None:
    config = write(tmp_path, "setup.cfg", "DIM spare\nPRINT missing\n")
    program = write(tmp_path, "main.mnt", CLEAN)
    once = json_records("--config", config, program)
    assert json_records("--config", config, config, program) == once
    assert [r["code"] for r in once if r["path"] == str(config)] == ["W103", "E3001"]


@pytest.mark.parametrize(
    ("data", "why"),
    [
        pytest.param(b"PRINT 1\n\x89PNG\x00\x1a\n" * 50, "2:5: not Mint text (a NUL byte)", id="binary"),
        # a byte order mark FF FE, then P 00 R 00 ...: the first NUL byte is the 4th, read as the 4th character
        pytest.param(
            "PRINT 1\r\n".encode("utf-16-le").join([b"\xff\xfe", b""]),
            "1:4: not Mint text (a NUL byte): UTF-16 text; save it as UTF-8",
            id="utf-16-little-endian",
        ),
        pytest.param(
            "PRINT 1\r\n".encode("utf-16-be").join([b"\xfe\xff", b""]),
            "1:3: not Mint text (a NUL byte): UTF-16 text; save it as UTF-8",
            id="utf-16-big-endian",
        ),
    ],
)
def test_a_binary_file_is_refused_with_where_its_nul_byte_is(tmp_path: Path, data: bytes, why: str) -> None:
    binary = tmp_path / "image.mnt"
    binary.write_bytes(data)
    result = mint_check(binary)
    assert result.exit_code == 2
    assert result.stderr == f"mint check: {binary}:{why}: not checked\n"
    assert mint_check("--config", binary, write(tmp_path, "app.mnt", CLEAN)).exit_code == 2


def test_a_program_named_as_its_own_configuration_exits_with_2(tmp_path: Path) -> None:
    program = write(tmp_path, "app.mnt", CLEAN)
    result = mint_check("--config", program, program)
    assert result.exit_code == 2
    assert f"--config {program} is the program {program} itself: name the configuration file" in result.stderr


def test_a_missing_config_file_exits_with_2(tmp_path: Path) -> None:
    program = write(tmp_path, "main.mnt", CLEAN)
    result = mint_check("--config", tmp_path / "absent.cfg", program)
    assert result.exit_code == 2
    assert result.stderr.startswith("mint check: ")
    assert "absent.cfg" in result.stderr
    assert "Traceback" not in result.output


# --------------------------------------------------------------------- files


def test_directories_are_searched_recursively_for_mnt_files(tmp_path: Path) -> None:
    top = write(tmp_path, "top.mnt", UNDECLARED)
    deep = write(tmp_path, "a/b/c/deep.MNT", UNDECLARED)
    write(tmp_path, "a/readme.txt", "PRINT b\n")
    records = json_records(tmp_path)
    assert sorted(r["path"] for r in records) == sorted([str(top), str(deep)])


def test_several_paths_are_each_reported_once(tmp_path: Path) -> None:
    path = write(tmp_path, "bad.mnt", UNDECLARED)
    records = json_records(path, tmp_path)
    assert [r["path"] for r in records] == [str(path)]


def test_a_cp1252_file_is_read_without_error(tmp_path: Path) -> None:
    path = tmp_path / "legacy.mnt"
    path.write_bytes("REM Réglage de la vitesse\r\nDIM a\r\na = 1\r\nPRINT a\r\n".encode("cp1252"))
    assert b"\xe9" in path.read_bytes()
    result = mint_check("--format", "json", path)
    assert result.exit_code == 0
    assert json.loads(result.stdout) == []
    assert result.stderr == ""


@pytest.mark.parametrize("output_format", ["text", "json", "sarif", "github"])
def test_every_format_exits_with_1_for_an_error(tmp_path: Path, output_format: str) -> None:
    path = write(tmp_path, "bad.mnt", UNDECLARED)
    assert mint_check("--format", output_format, path).exit_code == 1


# ----------------------------------------------------------- paths that fail


def test_a_link_loop_and_a_path_under_a_file_say_what_is_wrong(tmp_path: Path) -> None:
    loop = tmp_path / "loop.mnt"
    loop.symlink_to(loop)
    assert mint_check(loop).stderr.strip() == f"mint check: cannot read {loop}: Too many levels of symbolic links"
    under = write(tmp_path, "clean.mnt", CLEAN) / "x.mnt"
    assert mint_check(under).stderr.strip() == f"mint check: cannot read {under}: Not a directory"


def test_a_dangling_link_below_a_directory_is_reported_not_skipped(tmp_path: Path) -> None:
    write(tmp_path, "clean.mnt", CLEAN)
    (tmp_path / "gone.mnt").symlink_to(tmp_path / "nowhere.mnt")
    result = mint_check(tmp_path)
    assert result.exit_code == 2 and "gone.mnt" in result.stderr


def test_a_pipe_is_refused_instead_of_waited_on(tmp_path: Path) -> None:
    fifo = tmp_path / "pipe.mnt"
    os.mkfifo(fifo)
    result = mint_check(fifo)
    assert (result.exit_code, result.stderr.strip()) == (2, f"mint check: cannot read {fifo}: not a regular file")


@pytest.mark.parametrize(("option", "value"), [("--select", ""), ("--select", "E30001"), ("--ignore", "W9")])
def test_a_code_that_matches_nothing_is_a_usage_error(tmp_path: Path, option: str, value: str) -> None:
    result = mint_check(option, value, write(tmp_path, "bad.mnt", UNDECLARED))
    assert result.exit_code == 2 and option in result.stderr


# ------------------------------------------------------------ the code frame


def test_control_characters_of_the_source_never_reach_the_terminal(tmp_path: Path) -> None:
    result = mint_check(write(tmp_path, "escape.mnt", 'PRINT "\x1b]0;title\x07" b\n'))
    assert "\x1b" not in result.stdout and "\x07" not in result.stdout
    assert "\u241b]0;title\u2407" in result.stdout


def test_the_caret_counts_the_cells_of_wide_characters(tmp_path: Path) -> None:
    result = mint_check(write(tmp_path, "wide.mnt", 'PRINT "日本語" c\n'))
    source_line, caret_line = [line for line in result.stdout.splitlines() if "|" in line][1:3]
    cells_before_c = len('  1 | PRINT "') + 6 + len('" ')
    assert caret_line.index("^") == cells_before_c
    assert source_line.endswith("c")


def test_the_line_shown_is_the_line_of_the_error_after_a_page_break(tmp_path: Path) -> None:
    result = mint_check(write(tmp_path, "listing.mnt", "REM page one\x0cpage two\nPRINT missing\n"))
    assert "listing.mnt:2:7" in result.stdout
    source_line = next(line for line in result.stdout.splitlines() if line.startswith("  2 |"))
    assert source_line == "  2 | PRINT missing"


def test_a_long_line_is_shown_around_the_marked_text(tmp_path: Path) -> None:
    result = mint_check(write(tmp_path, "long.mnt", "DIM a\na = " + "1+" * 5000 + "1 : PRINT a\n"))
    assert max(len(line) for line in result.stdout.splitlines()) < 400
    assert "…" in result.stdout
