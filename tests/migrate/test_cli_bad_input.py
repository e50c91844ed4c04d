"""``mint-migrate`` on awkward input: every problem is one line with exit status 2, and
nothing is written that should not be (links, read-only files, binaries, half-done batches)."""

from __future__ import annotations

import errno
import json
import os
import stat
from collections.abc import Iterator
from pathlib import Path

import pytest
from click.testing import CliRunner, Result

from mintlang import atomic
from mintlang.migrate import cli as migrate_cli
from mintlang.migrate import migrate
from mintlang.migrate.context import Context

V3 = "DIM a(2)\nPRINT a(1)\nSTOP\n"
V4 = "AXES[0,1,2]\nDIM a(2)\nPRINT a(1)\nSTOP\n"


def run(*arguments: object) -> Result:
    return CliRunner().invoke(migrate_cli.migrate, [str(argument) for argument in arguments])


def program(directory: Path, name: str, text: str = V3) -> Path:
    path = directory / name
    path.write_text(text)
    return path


def one_line_usage_error(result: Result) -> str:
    assert result.exit_code == 2
    assert "Traceback" not in result.output and len(result.stderr.strip().splitlines()) == 1
    return result.stderr.strip()


# ------------------------------------------------------------------ the report


@pytest.mark.parametrize("name", ["demo.mnt", "x[/v3].mnt"])
def test_markup_in_a_program_or_its_path_is_printed_as_text(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, name: str
) -> None:
    monkeypatch.chdir(tmp_path)
    Path("x[").mkdir()
    program(Path(), name, 'DIM x\nPRINT x "[/b]"\nSTOP\n')
    result = run(name)
    assert result.exit_code == 0  # a manual item, not a crash
    message = "X-COMMENTED not valid Mint v3 either (Syntax error: unexpected '\"[/b]\"')"
    assert f"{name}:4 (original line 2): {message}" in result.output
    assert any(line.startswith(f" {name} ") and "program" in line for line in result.output.splitlines())


# ----------------------------------------------------------------- the modes


@pytest.mark.parametrize("modes", [["--check", "--write"], ["--write", "--check"], ["--write", "--stdout"]])
def test_two_modes_are_a_usage_error_and_nothing_is_written(tmp_path: Path, modes: list[str]) -> None:
    path = program(tmp_path, "a.mnt")
    assert "choose one of these modes" in one_line_usage_error(run(*modes, path))
    assert path.read_text() == V3


def test_the_program_as_its_own_configuration_is_a_usage_error(tmp_path: Path) -> None:
    path = program(tmp_path, "a.mnt")
    link = tmp_path / "link.cfg"
    link.symlink_to(path)
    for config in (path, link):
        message = one_line_usage_error(run("--write", "--config", config, path))
        assert message == f"mint-migrate: --config {config} is the program {path} itself: name the configuration file"
    assert path.read_text() == V3


def test_with_takes_optional_rules_only() -> None:
    message = one_line_usage_error(run("--with", "M-ABBR", "unused.mnt"))
    assert "not an optional rule: M-ABBR" in message and "M-BIT" in message and "S-IDLEAXES" in message


# ------------------------------------------------------------ what is written


def test_write_through_a_symbolic_link_rewrites_the_real_file_and_keeps_the_link(tmp_path: Path) -> None:
    real = program(tmp_path, "real.mnt")
    link = tmp_path / "link.mnt"
    link.symlink_to(real.name)
    assert run("--write", link).exit_code == 0
    assert link.is_symlink() and os.readlink(link) == "real.mnt"
    assert real.read_text() == V4


def test_write_keeps_hard_links_and_the_mode(tmp_path: Path) -> None:
    path = program(tmp_path, "a.mnt")
    path.chmod(0o640)
    other = tmp_path / "b.mnt"
    os.link(path, other)
    assert run("--write", path).exit_code == 0
    assert other.read_text() == V4 and path.stat().st_ino == other.stat().st_ino
    assert stat.S_IMODE(path.stat().st_mode) == 0o640
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.mnt", "b.mnt"]  # no backup left


def test_a_failed_write_of_a_hard_linked_file_leaves_every_name_as_it_was(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    path = program(tmp_path, "a.mnt")
    os.link(path, tmp_path / "b.mnt")

    def full_disk(handle: int, data: bytes, status: os.stat_result) -> None:
        os.write(handle, data[:3])
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(atomic, "_fill", full_disk)
    result = run("--write", path)
    assert result.exit_code == 2
    assert result.stderr.splitlines() == [
        f"mint-migrate: cannot write {path}: No space left on device",
        f"mint-migrate: 0 of 1 file written; not written: {path}",
    ]
    assert path.read_text() == V3 and (tmp_path / "b.mnt").read_text() == V3
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.mnt", "b.mnt"]  # no temporary file left


def test_a_read_only_file_is_refused_even_for_root(tmp_path: Path) -> None:
    path = program(tmp_path, "a.mnt")
    path.chmod(0o444)
    link = tmp_path / "link.mnt"
    link.symlink_to(path)
    message = one_line_usage_error(run("--write", path))
    assert message == f"mint-migrate: cannot write {path}: the file is read-only; nothing was written"
    message = one_line_usage_error(run("--write", link))
    assert message == f"mint-migrate: cannot write {link} (link to {path}): the file is read-only; nothing was written"
    assert path.read_text() == V3


def test_the_report_calls_a_file_that_was_not_written_so(tmp_path: Path) -> None:
    path = program(tmp_path, "a.mnt")
    path.chmod(0o444)
    result = run("--write", "--format", "json", path)
    assert result.exit_code == 2
    data = json.loads(result.stdout)
    assert data["files"][0]["status"] == "not written"
    assert (data["totals"]["changed"], data["totals"]["not_written"]) == (0, 1)
    text = run("--write", path).stdout
    assert "1 file: 0 changed, 0 unchanged, 1 not written;" in text


def test_files_that_are_not_regular_are_never_replaced(tmp_path: Path) -> None:
    pipe = tmp_path / "pipe.mnt"
    os.mkfifo(pipe)
    message = f"mint-migrate: {pipe}: cannot be read (not a regular file); left as it was"
    assert one_line_usage_error(run("--write", pipe)) == message
    with pytest.raises(atomic.Unwritable, match="not a regular file"):
        atomic.target(pipe)
    assert stat.S_ISFIFO(pipe.stat().st_mode)


def test_every_file_is_checked_before_the_first_is_written(tmp_path: Path) -> None:
    first = program(tmp_path, "a.mnt")
    locked = program(tmp_path, "b.mnt")
    locked.chmod(0o444)
    assert "b.mnt: the file is read-only; nothing was written" in one_line_usage_error(run("--write", tmp_path))
    assert first.read_text() == V3


def test_a_file_that_cannot_be_written_is_named_and_the_others_are_written(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    paths = [program(tmp_path, name) for name in ("a.mnt", "b.mnt", "c.mnt")]
    write = atomic.write

    def fails_on_b(real: Path, data: bytes, expected: bytes) -> None:
        if real.name == "b.mnt":
            raise OSError(errno.ENOSPC, "No space left on device")
        write(real, data, expected)

    monkeypatch.setattr(atomic, "write", fails_on_b)
    result = run("--write", tmp_path)
    assert result.exit_code == 2
    assert result.stderr.splitlines() == [
        f"mint-migrate: cannot write {paths[1]}: No space left on device",
        f"mint-migrate: 2 of 3 files written; not written: {paths[1]}",
    ]
    assert [path.read_text() for path in paths] == [V4, V3, V4]


def test_a_byte_order_mark_stays_first(tmp_path: Path) -> None:
    path = tmp_path / "bom.mnt"
    path.write_bytes(b"\xef\xbb\xbfREM x\nDIM a(2)\nPRINT a(1)\nSTOP\n")
    assert run("--write", path).exit_code == 0
    assert path.read_bytes() == b"\xef\xbb\xbfREM x\nAXES[0,1,2]\nDIM a(2)\nPRINT a(1)\nSTOP\n"


def test_a_byte_order_mark_does_not_move_the_changes() -> None:
    result = migrate("\ufeffHMSPEED = 10\n", controller="mintdrive", only=["M-REN"])
    assert result.text == "\ufeffHOMESPEED = 10\n"
    change = result.changes[0]
    assert result.source[change.span.start : change.span.end] == change.original == "HMSPEED"


def test_a_binary_file_is_refused_and_left_alone(tmp_path: Path) -> None:
    path = tmp_path / "binary.mnt"
    data = b"DIM a\nPR\x00\x01\x02INT a\n"
    path.write_bytes(data)
    message = one_line_usage_error(run("--write", path))
    assert message == f"mint-migrate: {path}:2:3: not Mint text (a NUL byte); left as it was"
    assert path.read_bytes() == data


# --------------------------------------------------------------- finding files


def test_a_link_loop_and_a_path_under_a_file_say_what_is_wrong(tmp_path: Path) -> None:
    loop = tmp_path / "loop.mnt"
    loop.symlink_to(loop)
    assert one_line_usage_error(run(loop)) == f"mint-migrate: cannot read {loop}: Too many levels of symbolic links"
    under = program(tmp_path, "plain.txt") / "x.mnt"
    assert one_line_usage_error(run(under)) == f"mint-migrate: cannot read {under}: Not a directory"


def test_an_unreadable_folder_is_reported_and_the_others_migrated(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    program(tmp_path, "a.mnt")
    locked = tmp_path / "locked"
    locked.mkdir()
    program(locked, "b.mnt")
    scandir = os.scandir

    def denied(path: str | Path = ".") -> Iterator[os.DirEntry[str]]:
        if Path(path) == locked:  # what mode 000 does to anyone without root's override
            raise PermissionError(errno.EACCES, "Permission denied", str(path))
        return scandir(path)

    monkeypatch.setattr(os, "scandir", denied)
    assert one_line_usage_error(run("--write", tmp_path)) == f"mint-migrate: cannot read {locked}: Permission denied"
    assert (tmp_path / "a.mnt").read_text() == V4


# ------------------------------------------------------------------ large input


def test_the_work_grows_linearly_with_the_program(monkeypatch: pytest.MonkeyPatch) -> None:
    """Rules used to rescan the whole application at each statement (5 MB took minutes)."""
    corpus = "".join(path.read_text() for path in sorted(Path("tests/corpus/v3/programs").glob("*.mnt")))
    visited = 0
    statements = Context.statements

    def counted(self: Context, *wanted: object) -> Iterator[object]:
        nonlocal visited
        for item in statements(self, *wanted):
            visited += 1
            yield item

    monkeypatch.setattr(Context, "statements", counted)

    def work(copies: int) -> int:
        nonlocal visited
        visited = 0
        migrate(corpus * copies)
        return visited

    assert work(4) <= 2.2 * work(2)
