"""``mint check`` on directories: unreadable entries, worker processes, stdin, and what the report shows (issue 17)."""

from __future__ import annotations

import importlib
import json
import os
from pathlib import Path

import pytest
from click.testing import CliRunner, Result

from mintlang.cli import main

CLEAN = "DIM a\na = 1\nPRINT a\n"
UNDECLARED = "DIM a\na = 1\nPRINT b\n"  # b: an error (E3001) at line 3, column 7


def mint_check(*arguments: str | Path, stdin: str | None = None) -> Result:
    return CliRunner().invoke(main, ["check", *map(str, arguments)], input=stdin)


def write(directory: Path, name: str, text: str) -> Path:
    path = directory / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


# ------------------------------------------------------ entries that cannot be read


def test_a_link_loop_a_pipe_and_a_dangling_link_are_reported_and_the_rest_is_checked(tmp_path: Path) -> None:
    write(tmp_path, "a.mnt", UNDECLARED)
    write(tmp_path, "z.mnt", UNDECLARED)
    (tmp_path / "loop.mnt").symlink_to(tmp_path / "loop.mnt")
    (tmp_path / "gone.mnt").symlink_to(tmp_path / "nowhere.mnt")
    os.mkfifo(tmp_path / "pipe.mnt")
    result = mint_check("--format", "json", tmp_path)
    assert result.exit_code == 2  # something was not checked
    found = json.loads(result.stdout)
    assert sorted(Path(r["path"]).name for r in found if r["code"] != "W120") == ["a.mnt", "z.mnt"]
    assert sorted(Path(r["path"]).name for r in found if r["code"] == "W120") == ["gone.mnt", "loop.mnt", "pipe.mnt"]
    assert sorted(result.stderr.splitlines()) == [
        f"mint check: cannot read {tmp_path / 'loop.mnt'}: Too many levels of symbolic links",
        f"mint check: cannot read {tmp_path / 'pipe.mnt'}: not a regular file",
        f"mint check: no such file or directory: {tmp_path / 'gone.mnt'}",
    ]


def test_entries_that_cannot_be_read_are_reported_in_the_order_of_their_paths(tmp_path: Path) -> None:
    names = ["b.mnt", "e.mnt", "a.mnt", "d.mnt", "c.mnt", "sub/a.mnt"]
    for name in names:
        (tmp_path / name).parent.mkdir(exist_ok=True)
        (tmp_path / name).symlink_to(tmp_path / "nowhere.mnt")
    result = mint_check(tmp_path)
    assert result.stderr.splitlines() == [
        f"mint check: no such file or directory: {tmp_path / name}" for name in sorted(names)
    ]


def test_a_file_deleted_after_it_was_found_is_reported_and_the_rest_is_checked(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    write(tmp_path, "a.mnt", CLEAN)
    doomed = write(tmp_path, "b.mnt", CLEAN)
    from mintlang.cli import files  # noqa: PLC0415

    found = files.find

    def find_then_delete(paths: object, **options: object) -> files.Found:
        result = found(paths, **options)  # type: ignore[arg-type]
        doomed.unlink()
        return result

    monkeypatch.setattr(importlib.import_module("mintlang.cli.check"), "find", find_then_delete)
    result = mint_check("--jobs", "1", tmp_path)
    assert result.exit_code == 2
    assert result.stderr == f"mint check: no such file or directory: {doomed}\n"
    assert "1 file checked: 0 errors" in result.stdout


def test_a_binary_file_in_a_directory_does_not_stop_the_others(tmp_path: Path) -> None:
    (tmp_path / "blob.mnt").write_bytes(b"PRINT 1\n\0\0")
    write(tmp_path, "ok.mnt", UNDECLARED)
    result = mint_check(tmp_path)
    assert result.exit_code == 2
    assert result.stderr == f"mint check: {tmp_path / 'blob.mnt'}:2:1: not Mint text (a NUL byte): not checked\n"
    assert "ok.mnt:3:7" in result.stdout


# ----------------------------------------------------------- worker processes


def test_the_report_is_the_same_whatever_the_number_of_processes(tmp_path: Path) -> None:
    for number in range(12):
        write(tmp_path / f"d{number % 3}", f"p{number:02}.mnt", UNDECLARED if number % 2 else CLEAN)
    one = mint_check("--format", "json", "-j", "1", tmp_path)
    many = mint_check("--format", "json", "-j", "3", tmp_path)
    assert one.exit_code == many.exit_code == 1
    assert one.stdout == many.stdout
    paths = [Path(record["path"]).relative_to(tmp_path).as_posix() for record in json.loads(one.stdout)]
    assert paths == sorted(paths)  # the order found: directories and names sorted
    assert len(paths) == 6


@pytest.mark.parametrize(
    ("files", "said"),
    [
        pytest.param({"a.mnt": CLEAN, "b.mnt": CLEAN, "c.mnt": CLEAN}, "3 of 3", id="three programs"),
        pytest.param({"a.mnt": CLEAN, "a.cfg": "", "b.mnt": CLEAN}, "3 of 3", id="a configuration file counts"),
        pytest.param({"a.mnt": CLEAN, "blob.mnt": "PRINT 1\n\0"}, "1 of 2", id="a file not checked counts"),
    ],
)
def test_verbose_says_how_many_files_on_how_many_processes(tmp_path: Path, files: dict[str, str], said: str) -> None:
    """The closing line counts a configuration file as a file checked: -v counts the same files."""
    for name, text in files.items():
        write(tmp_path, name, text)
    result = mint_check("-v", "-j", "2", tmp_path)
    assert result.stderr.splitlines()[-1].startswith(f"mint check: {said} files checked on 2 processes in ")


@pytest.mark.parametrize(
    "other_name",
    [
        pytest.param("../here/a.mnt", id="through the parent folder"),
        pytest.param("{folder}/a.mnt", id="absolute"),
        pytest.param(".", id="in the folder named"),
    ],
)
def test_a_file_named_twice_is_checked_and_fixed_once(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, other_name: str
) -> None:
    folder = tmp_path / "here"
    program = write(folder, "a.mnt", "PRINT \u201cx\u201d\n")  # W101: typographic quotes, a safe fix
    monkeypatch.chdir(folder)
    result = mint_check("--fix", "a.mnt", other_name.format(folder=folder))
    assert (result.exit_code, result.stderr) == (0, "")
    assert result.stdout.startswith("1 file checked: 0 errors, 0 warnings")
    assert program.read_text(encoding="utf-8") == 'PRINT "x"\n'


# ------------------------------------------------------------------ stdin


def test_a_program_read_from_stdin_is_reported_under_its_stdin_filename(tmp_path: Path) -> None:
    result = mint_check("-", "--stdin-filename", "cell.mnt", "--format", "json", stdin=UNDECLARED)
    assert result.exit_code == 1
    assert [(r["path"], r["line"], r["column"]) for r in json.loads(result.stdout)] == [("cell.mnt", 3, 7)]


@pytest.mark.parametrize(
    "on_disk",
    [
        pytest.param(None, id="no such file on disk"),
        pytest.param(CLEAN, id="another text on disk"),
    ],
)
def test_a_configuration_file_read_from_stdin_is_checked_as_given(tmp_path: Path, on_disk: str | None) -> None:
    name = tmp_path / "cell.cfg"
    if on_disk is not None:
        write(tmp_path, name.name, on_disk)
    result = mint_check("-", "--stdin-filename", name, "--format", "json", stdin=UNDECLARED)
    assert result.exit_code == 1, result.output
    assert [(r["path"], r["code"], r["line"], r["column"]) for r in json.loads(result.stdout)] == [
        (str(name), "E3001", 3, 7)
    ]


def test_stdin_without_a_name_is_called_dash() -> None:
    result = mint_check("-", stdin=CLEAN)
    assert result.exit_code == 0
    assert "1 file checked: 0 errors" in result.stdout


def test_a_stdin_filename_without_dash_is_a_usage_error(tmp_path: Path) -> None:
    result = mint_check(write(tmp_path, "a.mnt", CLEAN), "--stdin-filename", "x.mnt")
    assert result.exit_code == 2 and "give - as a path" in result.stderr


# -------------------------------------------------------- what is shown


def test_statistics_count_each_code_most_first(tmp_path: Path) -> None:
    write(tmp_path, "a.mnt", "DIM spare\nPRINT b\nPRINT c\n")  # W103 once, E3001 twice
    result = mint_check("--statistics", tmp_path)
    assert result.exit_code == 1
    lines = result.stdout.splitlines()
    assert [line.split()[:2] for line in lines] == [["2", "E3001"], ["1", "W103"]]
    records = json.loads(mint_check("--statistics", "--format", "json", tmp_path).stdout)
    assert [(r["code"], r["count"]) for r in records] == [("E3001", 2), ("W103", 1)]


def test_statistics_are_not_written_as_sarif(tmp_path: Path) -> None:
    result = mint_check("--statistics", "--format", "sarif", write(tmp_path, "a.mnt", CLEAN))
    assert result.exit_code == 2 and "--statistics" in result.stderr


def test_quiet_leaves_out_the_closing_count(tmp_path: Path) -> None:
    path = write(tmp_path, "a.mnt", UNDECLARED)
    quiet = mint_check("-q", path)
    assert "error[E3001]" in quiet.stdout
    assert "checked" not in quiet.stdout
    assert "1 file checked: 1 error" in mint_check(path).stdout


def test_a_thousand_diagnostics_are_all_shown_in_text(tmp_path: Path) -> None:
    source = "".join(f"PRINT b{n}\n" for n in range(1000))  # each line: E3001 at column 7
    result = mint_check(write(tmp_path, "many.mnt", source))
    assert result.stdout.count("error[E3001]") == 1000
    carets = [line.split("|")[1].strip() for line in result.stdout.splitlines() if line.rstrip().endswith("^")]
    assert len(carets) == 1000
    assert carets.count("^^^^") == 900  # under b100 to b999
    assert "\n1 file checked: 1000 errors, 0 warnings, 0 infos\n" in result.stdout  # then what --fix would fix


def test_ctrl_c_ends_the_run_with_130_and_one_line(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    def interrupted(*_: object, **__: object) -> list[object]:
        raise KeyboardInterrupt

    monkeypatch.setattr(importlib.import_module("mintlang.cli.check"), "map_in_order", interrupted)
    result = mint_check(write(tmp_path, "a.mnt", CLEAN))
    assert (result.exit_code, result.stderr, result.stdout) == (130, "mint check: interrupted\n", "")
