"""Keys typed on ``mint-run``'s standard input, for ``INPUT`` and ``INKEY`` (spec PR-5).

The manual's programs read the operator's terminal (000:12165-12171, 000:12202-12249); a
simulator's operator is whoever feeds its standard input, as in ``printf '42\\n' | mint-run
app.mnt``, or types at the terminal it runs in. Keys that are already there are taken as the
program asks for them, without waiting, so an ``INKEY`` polling loop runs on; the simulator waits
for more only when the program can go no further without them (a deadlock otherwise). Each byte
is one key (Latin-1), so no byte is lost.
"""

from __future__ import annotations

import os
import select
import sys
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager

from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.syntax.lexer import lex
from mintlang.syntax.tokens import TokenKind

_CHUNK = 65536


class StandardInput:
    """Keys read from a file descriptor: a pipe, a file or a terminal (``at_terminal``)."""

    def __init__(self, fd: int, before_wait: Callable[[], None] = lambda: None, *, at_terminal: bool = False) -> None:
        """``before_wait`` runs before blocking for more keys: the prompt the reader answers must be out."""
        self._fd: int | None = fd
        self._before_wait = before_wait
        self.at_terminal = at_terminal

    @property
    def ended(self) -> bool:
        """Whether every key has been read (end of file, or a descriptor that cannot be read)."""
        return self._fd is None

    def available(self) -> str:
        """The keys that can be read now without waiting; empty when there are none (yet)."""
        if self._fd is None:
            return ""
        try:
            ready, _, _ = select.select([self._fd], [], [], 0)
        except (OSError, ValueError):  # a descriptor select cannot watch (Windows pipes): wait() alone reads it
            return ""
        return self._read() if ready else ""

    def wait(self, timeout: float | None) -> str:
        """Block until keys come, for at most ``timeout`` seconds (None: for ever); empty at the end of the
        input, or when the time ran out (then not ``ended``)."""
        if self._fd is None:
            return ""
        self._before_wait()
        if timeout is not None:
            try:
                ready, _, _ = select.select([self._fd], [], [], timeout)
            except (OSError, ValueError):
                ready = [self._fd]  # select cannot watch it: read, waiting as long as that takes
            if not ready:
                return ""
        return self._read()

    def _read(self) -> str:
        assert self._fd is not None
        try:
            data = os.read(self._fd, _CHUNK)
        except OSError:
            data = b""
        if not data:
            self._fd = None
        return data.decode("latin-1")


def is_terminal() -> bool:
    """Whether standard input is a terminal someone types at."""
    try:
        return os.isatty(sys.stdin.fileno())
    except (AttributeError, ValueError, OSError):  # closed, or a stream of the caller's (click's CliRunner)
        return False


def reads_keys(sources: Iterable[str], dialect: Dialect) -> bool:
    """Whether the program or its configuration asks for keys (``INPUT``, ``INKEY``): only then does a run
    take the terminal's keys (and its mode), and give up the progress bar for them."""
    inkey = {"INKEY", *database().keywords["INKEY"].abbreviations}
    return any(
        token.kind is TokenKind.INPUT or (token.kind is TokenKind.KEYWORD and token.text.upper() in inkey)
        for source in sources
        for token in lex(source, dialect).tokens
    )


@contextmanager
def standard_input(before_wait: Callable[[], None], *, terminal: bool) -> Iterator[StandardInput | None]:
    """The process's standard input as keys while the run lasts; None when there is none to read, or it is
    a terminal and ``terminal`` is False (a program that asks for no key leaves the terminal as it is).

    A terminal gives each key as it is typed and shows none of them itself (its mode while the run
    lasts, restored after): the controller's terminal echoes what ``INPUT`` takes and nothing that
    ``INKEY`` reads, and the simulated one does the same on standard output.
    """
    try:
        fd = sys.stdin.fileno()
        os.fstat(fd)
    except (AttributeError, ValueError, OSError):
        yield None
        return
    if not os.isatty(fd):
        yield StandardInput(fd, before_wait)
        return
    if not terminal:
        yield None
        return
    import termios  # noqa: PLC0415 - a run at a terminal only
    import tty  # noqa: PLC0415

    saved = termios.tcgetattr(fd)
    tty.setcbreak(fd, termios.TCSANOW)  # keys typed ahead, before the run, are kept for it
    try:
        yield StandardInput(fd, before_wait, at_terminal=True)
    finally:
        termios.tcsetattr(fd, termios.TCSADRAIN, saved)
