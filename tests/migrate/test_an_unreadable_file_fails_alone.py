"""A file that cannot be read as Mint text (a NUL byte, a read error, a dangling link, a missing path) fails on
its own in a folder run, as a rule's failure does: it is named with where, left as it was (a failed file of the
report), the other files are still migrated in every mode, and the exit status is 2. Its application fails
with it: a program and its configuration file are read together, as the controller runs them, so neither is
migrated without the other."""

from __future__ import annotations

import errno
import json
import os
from pathlib import Path

import pytest
from click.testing import CliRunner, Result

from mintlang.migrate.cli import migrate as command

V3 = "DIM a(2)\nPRINT a(1)\nSTOP\n"
V4 = "AXES[0,1,2]\nDIM a(2)\nPRINT a(1)\nSTOP\n"  # v3 gave a program three axes; v4 must be told
BINARY = b"\xff\xfe\x00bad\n"  # the NUL byte is the third character: line 1, column 3


def run(*arguments: object) -> Result:
    return CliRunner().invoke(command, [str(argument) for argument in arguments])


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    (tmp_path / "a.mnt").write_text(V3)
    (tmp_path / "b.mnt").write_bytes(BINARY)
    (tmp_path / "c.mnt").write_text(V3)
    return tmp_path


def problems(result: Result) -> list[str]:
    assert "Traceback" not in result.output
    return result.stderr.splitlines()


@pytest.mark.parametrize("mode", ["--diff", "--check", "--write", "--verify"])
def test_the_other_files_are_migrated_in_every_mode(folder: Path, mode: str) -> None:
    result = run(mode, folder)
    assert result.exit_code == 2
    assert problems(result) == [f"mint-migrate: {folder / 'b.mnt'}:1:3: not Mint text (a NUL byte); left as it was"]
    assert (folder / "b.mnt").read_bytes() == BINARY
    if mode == "--write":
        assert [(folder / name).read_text() for name in ("a.mnt", "c.mnt")] == [V4, V4]
    elif mode == "--verify":
        assert "2 applications verified: 2 equivalent" in result.stdout
    else:
        assert result.stdout.count("+AXES[0,1,2]") == (2 if mode == "--diff" else 0)
        assert "3 files: 2 changed, 0 unchanged, 1 failed;" in result.stdout


def test_the_json_report_gives_the_failed_file_and_where(folder: Path) -> None:
    result = run("--format", "json", folder)
    assert result.exit_code == 2
    rows = {Path(row["path"]).name: row for row in json.loads(result.stdout)["files"]}
    assert [rows[name]["status"] for name in ("a.mnt", "b.mnt", "c.mnt")] == ["changed", "failed", "changed"]
    failure = {"rule": None, "reason": "not Mint text (a NUL byte)", "line": 1, "column": 3}
    assert rows["b.mnt"]["failure"] == failure


def test_a_program_whose_configuration_file_cannot_be_read_is_not_migrated_alone(tmp_path: Path) -> None:
    program, configuration = tmp_path / "cell.mnt", tmp_path / "cell.cfg"
    program.write_text(V3)
    configuration.write_bytes(b"SPEED = 10\n\x00\n")
    other = tmp_path / "other.mnt"
    other.write_text(V3)
    result = run("--write", tmp_path)
    assert result.exit_code == 2
    assert problems(result) == [
        f"mint-migrate: {configuration}:2:1: not Mint text (a NUL byte); left as it was",
        f"mint-migrate: {program}: its configuration file {configuration} cannot be read; left as it was",
    ]
    assert (program.read_text(), other.read_text()) == (V3, V4)


def test_a_configuration_file_whose_program_cannot_be_read_is_not_migrated_alone(tmp_path: Path) -> None:
    program, configuration = tmp_path / "cell.mnt", tmp_path / "cell.cfg"
    program.write_bytes(b"PRINT 1\x00")
    configuration.write_text("GEARN = 1\n")  # a v3 keyword the migration would rewrite
    result = run("--write", "--config", configuration, program)
    assert result.exit_code == 2
    assert problems(result) == [
        f"mint-migrate: {configuration}: its program {program} cannot be read; left as it was",
        f"mint-migrate: {program}:1:8: not Mint text (a NUL byte); left as it was",
    ]
    assert configuration.read_text() == "GEARN = 1\n"


def test_a_dangling_link_and_a_missing_path_are_named_and_the_others_migrated(tmp_path: Path) -> None:
    (tmp_path / "a.mnt").write_text(V3)
    (tmp_path / "gone.mnt").symlink_to(tmp_path / "nowhere.mnt")
    missing = tmp_path / "typo.mnt"
    result = run("--write", tmp_path, missing)
    assert result.exit_code == 2
    assert problems(result) == [
        f"mint-migrate: no such file or directory: {tmp_path / 'gone.mnt'}",
        f"mint-migrate: no such file or directory: {missing}",
    ]
    assert (tmp_path / "a.mnt").read_text() == V4


def test_a_file_that_cannot_be_read_is_named_with_the_reason(folder: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    read_bytes = Path.read_bytes

    def denied(path: Path) -> bytes:
        if path.name == "b.mnt":  # what mode 000 does to anyone without root's override
            raise PermissionError(errno.EACCES, "Permission denied", str(path))
        return read_bytes(path)

    monkeypatch.setattr(Path, "read_bytes", denied)
    result = run("--write", folder)
    assert result.exit_code == 2
    assert problems(result) == [f"mint-migrate: {folder / 'b.mnt'}: cannot be read (Permission denied); left as it was"]
    assert [(folder / name).read_text() for name in ("a.mnt", "c.mnt")] == [V4, V4]


def test_a_missing_path_named_beside_others_is_a_failed_file_of_the_json_report(tmp_path: Path) -> None:
    (tmp_path / "a.mnt").write_text(V3)
    missing, configuration = tmp_path / "typo.mnt", tmp_path / "gone" / "cell.cfg"
    result = run("--format", "json", tmp_path / "a.mnt", missing, configuration)
    assert result.exit_code == 2
    data = json.loads(result.stdout)
    failure = {"rule": None, "reason": "no such file or directory"}
    assert [(row["path"], row["role"], row["status"], row.get("failure")) for row in data["files"]] == [
        (str(tmp_path / "a.mnt"), "program", "changed", None),
        (str(missing), "program", "failed", failure),
        (str(configuration), "configuration", "failed", failure),
    ]
    assert (data["totals"]["changed"], data["totals"]["failed"]) == (1, 2)
    assert problems(result) == [
        f"mint-migrate: no such file or directory: {missing}",
        f"mint-migrate: no such file or directory: {configuration}",
    ]


def test_the_text_report_counts_a_missing_path_as_failed(tmp_path: Path) -> None:
    (tmp_path / "a.mnt").write_text(V3)
    result = run("--check", tmp_path / "a.mnt", tmp_path / "typo.mnt")
    assert result.exit_code == 2
    assert "2 files: 1 changed, 0 unchanged, 1 failed;" in result.stdout


def test_a_folder_without_programs_is_named(tmp_path: Path) -> None:
    (tmp_path / "notes.txt").write_text("not a program\n")
    result = run(tmp_path)
    assert result.exit_code == 2
    assert problems(result) == [f"mint-migrate: no .mnt or .cfg files to migrate in {tmp_path}"]


def test_a_folder_that_cannot_be_listed_is_a_failed_folder_of_the_json_report(
    folder: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    locked = folder / "locked"
    locked.mkdir()
    scandir = os.scandir

    def denied(path: str | Path) -> object:
        if Path(path) == locked:  # what mode 000 does to anyone without root's override
            raise PermissionError(errno.EACCES, "Permission denied", str(path))
        return scandir(path)

    monkeypatch.setattr(os, "scandir", denied)
    data = json.loads(run("--format", "json", folder).stdout)
    (row,) = [row for row in data["files"] if row["path"] == str(locked)]
    assert (row["role"], row["status"]) == ("folder", "failed")
