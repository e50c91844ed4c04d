"""``mint check --watch`` (ruff's ``--watch``): the check runs again whenever a file it reads changes, until Ctrl-C.

A file it reads: a program, a configuration file, a settings file of its folder or of one above. Ctrl-C ends
the watch with exit status 0 and no traceback.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from mintlang.cli import watching
from mintlang.settings import Overrides
from tests.cli.invoking import mint_check, write


def _seen(folder: Path) -> watching.Seen:
    return watching.seen([folder], Overrides())


def _saved(path: Path, text: str) -> None:
    """``text`` written as an editor saves it: a later modification time even on a coarse clock."""
    path.write_text(text, encoding="utf-8")
    later = path.stat().st_mtime_ns + 1_000_000_000
    os.utime(path, ns=(later, later))


@pytest.mark.parametrize(
    ("name", "text"),
    [
        ("cell.mnt", "PRINT 2\n"),  # the program saved
        ("cell.cfg", "DIM speed_setting\n"),  # its configuration file appears
        ("other.mnt", "PRINT 3\n"),  # a new program in the folder
        ("mint.toml", 'controller = "nextmove-bx"\n'),  # the settings
    ],
)
def test_a_file_the_check_reads_changes_what_is_seen(tmp_path: Path, name: str, text: str) -> None:
    write(tmp_path / "cell.mnt", "PRINT 1\n")
    before = _seen(tmp_path)
    _saved(tmp_path / name, text)
    assert _seen(tmp_path) != before


def test_settings_above_the_folder_are_watched(tmp_path: Path) -> None:
    write(tmp_path / "line" / "cell.mnt", "PRINT 1\n")
    before = _seen(tmp_path / "line")
    _saved(tmp_path / "pyproject.toml", "[tool.mint]\ndialect = 'v4'\n")
    assert _seen(tmp_path / "line") != before


def test_other_files_are_not(tmp_path: Path) -> None:
    write(tmp_path / "cell.mnt", "PRINT 1\n")
    before = _seen(tmp_path)
    _saved(tmp_path / "notes.txt", "the cell's wiring\n")
    assert _seen(tmp_path) == before


def test_the_check_runs_again_after_each_change_and_ctrl_c_ends_it(monkeypatch: pytest.MonkeyPatch) -> None:
    states = iter(["first", "first", "second", "second", "second"])
    checks: list[int] = []

    def sleep(_: float) -> None:
        if len(checks) == 2:
            raise KeyboardInterrupt

    monkeypatch.setattr(watching.time, "sleep", sleep)
    watching.watch(lambda: checks.append(len(checks)) or 0, lambda: next(states), clear=False)
    assert checks == [0, 1]


def test_each_check_ends_with_what_its_exit_status_says(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    # README, Watching: 0 passed (warnings alone), 1 failed, 2 a file or setting that could not be checked
    codes = iter([2, 1, 0])
    states = iter(["first", "second", "second", "third", "third", "third"])

    def sleep(_: float) -> None:
        raise KeyboardInterrupt

    monkeypatch.setattr(watching.time, "sleep", sleep)
    watching.watch(lambda: next(codes), lambda: next(states), clear=False)
    endings = [line.split("] ", 1)[1] for line in capsys.readouterr().err.splitlines() if "] " in line]
    assert endings == [
        "could not check everything; watching for changes (Ctrl-C to stop)",
        "failed; watching for changes (Ctrl-C to stop)",
        "passed; watching for changes (Ctrl-C to stop)",
    ]


@pytest.mark.parametrize("extra", [["-"], ["--add-ignore"], ["--show-settings"]])
def test_it_watches_files_only(tmp_path: Path, extra: list[str]) -> None:
    result = mint_check("--watch", write(tmp_path / "cell.mnt", "PRINT 1\n"), *extra)
    assert result.exit_code == 2 and "--watch checks files as they change" in result.output


def _line_with(stream: object, text: str, deadline: float) -> str:
    while time.monotonic() < deadline:
        line = stream.readline()  # type: ignore[attr-defined]
        if text in line:
            return line
    raise AssertionError(f"no line with {text!r}")


def test_watching_a_folder_as_a_user_does(tmp_path: Path) -> None:
    """Each check ends with a line saying when it ran and whether it passed, as its exit status would say: a
    warning left does not fail it (README, Exit status), and it is no claim that nothing was found."""
    program = write(tmp_path / "cell.mnt", "PRINT bar\n")
    command = [sys.executable, "-m", "mintlang", "check", "--watch", str(tmp_path)]
    with subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True) as watcher:
        try:  # the watch is ended whatever is read: a line not as expected must not leave the test waiting on it
            deadline = time.monotonic() + 60
            first = _line_with(watcher.stderr, "watching", deadline)
            _saved(program, "DIM bar\nDIM spare\nPRINT bar\n")  # an unused variable: a warning
            second = _line_with(watcher.stderr, "watching", deadline)
        finally:
            watcher.send_signal(signal.SIGINT)
            output, errors = watcher.communicate(timeout=60)
    assert "] failed; watching for changes" in first
    assert "] passed; watching for changes" in second
    assert watcher.returncode == 0 and "Traceback" not in errors
    assert "error[E3001]" in output and output.endswith("1 file checked: 0 errors, 1 warning, 0 infos\n")
