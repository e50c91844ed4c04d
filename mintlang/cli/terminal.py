"""Where a tool's output goes and whether it is coloured (``--color``, ``NO_COLOR``, ``--output-file``).

rich decides what a stream can show (a terminal, ``TERM=dumb``, ``NO_COLOR``,
``FORCE_COLOR``); ``--color always`` and ``never`` override it, as the
NO_COLOR convention asks of a command-line option. rich is imported here only
when a console is made, so ``--version`` and ``--help`` never pay for it.
"""

from __future__ import annotations

import io
import os
import sys
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager
from functools import cache
from pathlib import Path
from typing import IO, TYPE_CHECKING, NoReturn

from mintlang.cli.files import same_file
from mintlang.records import record

if TYPE_CHECKING:
    from rich.console import Console

COLOR_CHOICES = ("auto", "always", "never")
BROKEN_PIPE = 141  # 128 + SIGPIPE: what a shell reports for a writer whose reader went away (``| head``)


def console(color: str = "auto", *, stderr: bool = False, file: IO[str] | None = None) -> Console:
    """A rich console for ``--color``: markup and highlighting of the tools' own text only, no wrapping.

    No emoji codes either: rich showed ``dir:100:x.mnt`` as ``dir💯x.mnt`` (``escape`` leaves ``:name:``
    alone), and a tiny migration spent 1.6 % of its instructions reading rich's table of codes."""
    settings: dict[str, object] = {
        "file": file,
        "stderr": stderr,
        "highlight": False,
        "soft_wrap": True,
        "emoji": False,
    }
    if color == "never":
        settings["color_system"] = None
    elif color == "always":
        settings |= {"force_terminal": True, "no_color": False}
    return _tool_console()(**settings)  # type: ignore[arg-type]


@cache
def _tool_console() -> type[Console]:
    """rich's console, except that a reader that goes away ends the tool as ``reader_may_leave`` does
    (rich's own choice is exit status 1, which says the tool failed)."""
    from rich.console import Console  # noqa: PLC0415 - rich costs a tenth of the start-up

    class ToolConsole(Console):
        def on_broken_pipe(self) -> None:
            self.quiet = True
            discard_standard_output()
            sys.exit(BROKEN_PIPE)

    return ToolConsole


def colour_console(color: str, file: IO[str]) -> Console | None:
    """A rich console for a report to ``file`` that may show colour; None where it shows none."""
    return console(color, file=file) if may_show_colour(color, file) else None


def may_show_colour(color: str, file: IO[str]) -> bool:
    """Whether output to ``file`` may be coloured, as far as can be told without importing rich.

    False is certain: ``--color never``, or ``auto`` into a file or pipe (a pre-commit hook, CI)
    with neither ``FORCE_COLOR`` nor ``TTY_COMPATIBLE`` set, which rich reads before asking the
    stream whether it is a terminal. True leaves the answer to rich (``TERM=dumb``, ``NO_COLOR``).
    """
    if color == "never":
        return False
    return color != "auto" or _isatty(file) or bool({"FORCE_COLOR", "TTY_COMPATIBLE"} & os.environ.keys())


class Messages:
    """A tool's own lines on standard output or error: through rich where they may be coloured, else written
    as they are, without importing rich (a run into a pipe).

    A line rich would change (a tab it expands, a control character it drops) still goes through rich,
    so the output is the same either way; ``console`` is rich's, for what only rich writes (a table).
    """

    def __init__(self, color: str, *, stderr: bool = False, rich: bool = False) -> None:
        """``rich``: through rich whatever the stream (a progress bar shares it)."""
        self.color = color
        self.stderr = stderr
        self._console = console(color, stderr=stderr) if rich or may_show_colour(color, self._stream()) else None

    @property
    def console(self) -> Console:
        """rich's console for the stream, made when first needed."""
        if self._console is None:
            self._console = console(self.color, stderr=self.stderr)
        return self._console

    def line(self, text: str, style: str = "") -> None:
        """``text`` on a line of its own, in rich's ``style`` where colour shows; never read as markup."""
        if self._console is None and text.isprintable():
            self._stream().write(f"{text}\n")
            return
        from rich.text import Text  # noqa: PLC0415 - rich costs a tenth of the start-up

        self.console.print(Text(text, style=style), highlight=False)

    def _stream(self) -> IO[str]:
        return sys.stderr if self.stderr else sys.stdout


def discard_standard_output() -> None:
    """Send what a tool still writes to standard output (buffered text, a report) nowhere: its reader went away,
    and Python's own flush at exit would otherwise fail once more, with a message of its own."""
    os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())


def write_in_pieces(stream: IO[str], text: str) -> None:
    """Write ``text`` a buffer's worth at a time, so that a reader that goes away is noticed: one large write
    to a pipe whose reader leaves half way returns short, and Python's buffered writer drops the rest without
    an error, where the next write of a piece raises ``BrokenPipeError`` for ``reader_may_leave``."""
    size = io.DEFAULT_BUFFER_SIZE
    for start in range(0, len(text), size):
        stream.write(text[start : start + size])


@contextmanager
def reader_may_leave() -> Iterator[None]:
    """A tool's whole output to standard output; a reader that stops reading (``| head -1``) ends the tool
    quietly with ``BROKEN_PIPE``, as a shell tool killed by SIGPIPE would, not with click's exit status 1."""
    try:
        try:
            yield
        finally:  # also on sys.exit: what is still buffered must reach the reader before the status is known
            sys.stdout.flush()
    except BrokenPipeError:
        discard_standard_output()
        sys.exit(BROKEN_PIPE)


def _isatty(file: IO[str]) -> bool:
    try:
        return file.isatty()
    except ValueError:  # closed
        return False


_SOURCE_SUFFIXES = (".mnt", ".cfg")


def refuse_overwriting(path: Path | None, inputs: Iterable[Path], fail: Callable[[str], NoReturn]) -> None:
    """An output file (``--output-file``, ``--lcov``) never takes the place of an input or of a Mint source:
    the report would silently replace the program it is about."""
    if path is None:
        return
    if path.name.lower().endswith(_SOURCE_SUFFIXES) and path.exists():
        fail(f"cannot write {path}: it is a Mint source file, not a report")
    for source in inputs:
        if same_file(path, source):  # an input exists, so an output that is the same file does too
            fail(f"cannot write {path}: it is also an input")


@contextmanager
def destination(path: Path | None, fail: Callable[[str], NoReturn], *, stderr: bool = False) -> Iterator[IO[str]]:
    """Standard output (or error), or the ``--output-file``; one that cannot be opened is ``fail``'s one line."""
    if path is None:
        yield sys.stderr if stderr else sys.stdout
        return
    try:
        stream = path.open("w", encoding="utf-8")
    except OSError as error:
        fail(f"cannot write {path}: {error.strerror or error}")
    with stream:
        yield stream


@record
class Palette:
    """The escape codes of a few rich styles, rendered once for a console.

    Painting a piece of text is then two string joins: a report of ten thousand
    diagnostics is written in a fraction of the time ``Console.print`` takes per line.
    """

    codes: dict[str, tuple[str, str]]

    @classmethod
    def for_console(cls, console: Console, styles: Iterable[str]) -> Palette:
        from rich.color import ColorSystem  # noqa: PLC0415
        from rich.style import Style  # noqa: PLC0415

        systems = {"standard": ColorSystem.STANDARD, "256": ColorSystem.EIGHT_BIT, "truecolor": ColorSystem.TRUECOLOR}
        system = systems.get(console.color_system or "")
        if system is None:  # no colour, or Windows' legacy console, which rich styles by API calls, not codes
            return cls({})
        codes: dict[str, tuple[str, str]] = {}
        for name in styles:
            style = Style.parse(name)
            if console.no_color:
                style = style.without_color
            before, _, after = style.render("\0", color_system=system).partition("\0")
            codes[name] = (before, after)
        return cls(codes)

    def paint(self, style: str, text: str) -> str:
        """``text`` in ``style``; as it is when the console shows no styles."""
        before, after = self.codes.get(style, ("", ""))
        return f"{before}{text}{after}"
