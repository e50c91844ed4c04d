"""Keys typed at the terminal ``mint-run`` runs in answer ``INPUT`` and ``INKEY``, as at the controller's.

A program that asks for keys gets each one as it is typed, Enter or not: ``INKEY`` returns a
key's code as soon as it is pressed (000:12165-12171). The terminal shows none of the keys itself;
the controller echoes each key ``INPUT`` takes as it comes (000:12202-12220), so each typed digit
appears once, after the prompt, which is on the screen before the program waits, with no progress
bar holding its line back. The terminal's own mode comes back when the run ends. A program that
asks for no key leaves the terminal as it is and keeps the progress bar.
"""

from __future__ import annotations

import os
import pty
import select
import subprocess
import sys
import termios
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest


class Terminal:
    """A pseudo-terminal with ``mint-run`` on its far side: what it shows, what is typed into it."""

    def __init__(self, program: Path, *, whole_screen: bool = False) -> None:
        """``whole_screen``: standard error on the terminal too, without ``-q`` (the progress bar's place)."""
        self.master, self.slave = pty.openpty()
        self.mode = termios.tcgetattr(self.slave)  # as the shell left it
        self.shown = b""
        quiet = () if whole_screen else ("-q",)
        self.process = subprocess.Popen(
            [sys.executable, "-m", "mintlang.runtime", *quiet, "--max-wall-s", "60", str(program)],
            stdin=self.slave,
            stdout=self.slave,
            stderr=self.slave if whole_screen else subprocess.PIPE,
        )

    def wait_for(self, text: bytes, seconds: float = 60.0) -> None:
        """Read what the terminal shows until ``text`` is on it."""
        deadline = time.monotonic() + seconds
        while text not in self.shown:
            assert time.monotonic() < deadline, f"{text!r} never shown; shown: {self.shown!r}"
            ready, _, _ = select.select([self.master], [], [], 0.1)
            if ready:
                self.shown += os.read(self.master, 4096)

    def type(self, keys: bytes) -> None:
        os.write(self.master, keys)

    def close(self) -> None:
        self.process.kill()
        self.process.wait()
        os.close(self.master)
        os.close(self.slave)


@pytest.fixture
def terminal(tmp_path: Path) -> Iterator[Callable[..., Terminal]]:
    opened: list[Terminal] = []

    def open_on(text: str, *, whole_screen: bool = False) -> Terminal:
        path = tmp_path / "typed.mnt"
        path.write_text(text, encoding="utf-8")
        opened.append(Terminal(path, whole_screen=whole_screen))
        return opened[-1]

    yield open_on
    for each in opened:
        each.close()


def test_input_takes_the_number_typed_and_echoes_it_once(terminal: Callable[..., Terminal]) -> None:
    screen = terminal('DIM a\nINPUT "value", a\nPRINT "got ", a * 2\n')
    screen.wait_for(b"value")  # the prompt is out before the program waits
    screen.type(b"2")
    screen.wait_for(b"value2")  # each key shows as it is typed, before Enter
    screen.type(b"1\r")
    screen.wait_for(b"got 42")
    assert screen.process.wait(timeout=60) == 0
    assert screen.shown.count(b"21") == 1  # the controller's echo, not the terminal's too


def test_inkey_reads_a_key_without_enter(terminal: Callable[..., Terminal]) -> None:
    screen = terminal('DIM k\nPRINT "press"\nREPEAT\n  k = INKEY\nUNTIL k <> 0\nPRINT "code ", k\n')
    screen.wait_for(b"press")
    screen.type(b"y")
    screen.wait_for(b"code 89")  # 'y' upper-cased: the key is read as pressed, no Enter
    assert screen.process.wait(timeout=60) == 0


def test_the_terminal_mode_comes_back_when_the_run_ends(terminal: Callable[..., Terminal]) -> None:
    screen = terminal('PRINT "ready"\nPAUSE INKEY\n')
    screen.wait_for(b"ready")
    screen.type(b"q")
    assert screen.process.wait(timeout=60) == 0
    assert termios.tcgetattr(screen.slave) == screen.mode


def test_a_program_that_asks_for_no_key_keeps_the_progress_bar(terminal: Callable[..., Terminal]) -> None:
    screen = terminal('WAIT = 5000\nPRINT "done"\n', whole_screen=True)
    screen.wait_for(b"done")
    assert screen.process.wait(timeout=60) == 0
    assert b"simulated" in screen.shown  # the bar, while the simulated 5 s go by


def test_a_program_that_asks_for_keys_has_no_progress_bar_under_them(terminal: Callable[..., Terminal]) -> None:
    screen = terminal('WAIT = 5000\nPRINT "key?"\nPAUSE INKEY\n', whole_screen=True)
    screen.wait_for(b"key?")
    screen.type(b"k")
    assert screen.process.wait(timeout=60) == 0
    assert b"simulated" not in screen.shown
