"""The simulated operator terminal: one merged output stream and one keyboard buffer (spec PR-4, PR-5).

The output streams to the caller as it is written and only its latest part is
kept, so a run that prints for minutes stays small; text an expectation looks
for is watched as it streams past, so a check does not depend on what is kept.

Output is plain text meant for a log, so screen-control commands degrade to
what a log can show: ``CLS`` ends the current line, ``LOCATE`` pads with spaces
to the column, ``BEEP`` writes the BEL character and ``BOL`` a carriage return. The column is tracked because
``;`` tab stops depend on it.
"""

from __future__ import annotations

import re
from collections import deque
from collections.abc import Callable, Sequence
from itertools import islice
from typing import Protocol

from mintlang.records import record
from mintlang.runtime.errors import MintError
from mintlang.runtime.numbers import f32, held

TAB_WIDTH = 8
TRANSCRIPT_LIMIT = 1 << 20
"""Characters of output a run keeps, the latest; a program printing in a loop must not fill the memory."""
NEWLINE = "\n"
BELL = "\a"
_LINE_ENDS = "\r\n"
_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)")


@record
class NumberEntry:
    """A line typed at ``INPUT``: a number, ``value=None`` for an empty line (keep the variable), or ``retry``.

    The manual asks for the number again when the entry is not numeric, and keeps
    the variable's value on a bare return; the runtime prints its prompt again on ``retry``.
    """

    value: float | None
    retry: bool = False
    typed: str = ""  # the number as typed, before binary32 rounds it (INPUT .. USING counts its digits)


class Keyboard(Protocol):
    """Keys from outside the scenario (``mint-run``'s standard input): those there now, or wait for more."""

    @property
    def ended(self) -> bool: ...

    @property
    def at_terminal(self) -> bool:
        """Whether someone types the keys as the run goes: they see each key INPUT takes as it comes."""
        ...

    def available(self) -> str: ...

    def wait(self, timeout: float | None) -> str: ...


class Terminal:
    """Collects everything the program prints and serves scripted keystrokes to ``INKEY`` and ``INPUT``."""

    def __init__(self, echo: Callable[[str], None] | None = None) -> None:
        """``echo`` receives each piece of output as it is written, so a caller can stream it live."""
        self._chunks: list[str] = []
        self._kept = 0  # characters in _chunks
        self._echo = echo
        self._keys: deque[str] = deque()
        self._no_line_end = 0  # keys at the front of _keys known to hold no line end: each key is searched once
        self._shown = 0  # keys at the front of _keys INPUT echoed as they were typed at a terminal
        self._after_cr = False  # INPUT took a CR that ended the keys: an LF typed next belongs to it (CR LF)
        self._watched: dict[str, str | None] = {}  # text -> the output that may begin it, None once printed
        self.column = 0
        self.printed = 0  # characters written in all, kept or not
        self.query = ""  # what INPUT prints after its prompt: nothing in v4; Mint v3's "?" while PON is in force
        self.keyboard: Keyboard | None = None  # keys typed besides the scenario's, taken as the program asks

    @property
    def text(self) -> str:
        """What was written so far: all of it, or its last ``TRANSCRIPT_LIMIT`` characters."""
        return "".join(self._chunks)[-TRANSCRIPT_LIMIT:]

    @property
    def dropped(self) -> int:
        """Characters written that ``text`` no longer holds."""
        return self.printed - min(self._kept, TRANSCRIPT_LIMIT)

    def watch(self, text: str) -> None:
        """Look for ``text`` in everything written from now on, so ``has_printed`` knows however much is dropped."""
        if text not in self._watched:
            self._watched[text] = None if text in self.text else self._carry(text, self.text)

    def has_printed(self, text: str) -> bool:
        """Whether ``text`` was written (across writes and lines); exact for watched text, else within ``text``."""
        if text in self._watched:
            return self._watched[text] is None
        return text in self.text

    @staticmethod
    def _carry(wanted: str, window: str) -> str:
        """The end of ``window`` that the next write could complete into ``wanted``."""
        return window[max(0, len(window) - len(wanted) + 1) :]

    def write(self, text: str) -> None:
        """Append raw text; CR or LF returns the column to 0, other control characters take no column."""
        if not text:
            return
        for wanted, carry in self._watched.items():
            if carry is not None:
                window = carry + text
                self._watched[wanted] = None if wanted in window else self._carry(wanted, window)
        self._chunks.append(text)
        self._kept += len(text)
        self.printed += len(text)
        if self._kept > 2 * TRANSCRIPT_LIMIT:  # trimming only now and then keeps writing cheap
            self._chunks = [self.text]
            self._kept = TRANSCRIPT_LIMIT
        if self._echo is not None:
            self._echo(text)
        self.column = _column_after(self.column, text)

    def newline(self) -> None:
        self.write(NEWLINE)

    def announce(self, message: str) -> None:
        """A message of the controller's own (an error that stops the program), on a line of its own."""
        self.write((NEWLINE if self.column else "") + message + NEWLINE)

    def print_items(self, items: Sequence[tuple[str, str | None]], newline: bool) -> None:
        """Render one ``PRINT`` from already formatted items, each with the separator after it.

        ``,`` joins the next item directly, ``;`` moves to the next tab stop. A
        separator after the last item suppresses the line feed (PR-4 RC), and the
        ``;`` padding still happens. ``newline=False`` never ends the line, for prompts.
        The whole statement is one write, so a live terminal gets it in one piece.
        """
        pieces = []
        column = self.column
        for text, separator in items:
            pieces.append(text)
            column = _column_after(column, text)
            if separator == ";":
                padding = " " * (TAB_WIDTH - column % TAB_WIDTH)
                pieces.append(padding)
                column += len(padding)
        if newline and (not items or items[-1][1] is None):
            pieces.append(NEWLINE)
        self.write("".join(pieces))

    def cls(self) -> None:
        """``CLS``: a log cannot be cleared, so only the current line is ended and the cursor is at column 0."""
        if self.column:
            self.newline()

    def bol(self) -> None:
        """``BOL``: back to the start of the current line, the carriage return ``PRINT CHR(13)`` sends
        (000:7401-7421); what is printed next overwrites the line on a screen."""
        self.write("\r")

    def beep(self) -> None:
        """``BEEP``: the BEL character, the same byte ``PRINT CHR(7)`` sends."""
        self.write(BELL)

    def locate(self, column: int, row: int) -> None:
        """``LOCATE``: rows are ignored; the column is reached with spaces, on a new line if already past it.

        Out-of-range coordinates (below 1) leave the cursor where it is, as the manual describes.
        """
        if column < 1 or row < 1:
            return
        target = column - 1
        if target < self.column:
            self.newline()
        self.write(" " * (target - self.column))

    def prompt(self, text: str) -> str:
        """What ``INPUT`` prints before it waits: its prompt, then the query mark (after a space) if any."""
        if not self.query:
            return text
        return f"{text} {self.query}" if text else self.query

    def type_keys(self, text: str) -> None:
        """Queue scripted keystrokes; ``INKEY`` and ``INPUT`` consume them in order."""
        self._keys.extend(text)

    def inkey(self) -> int:
        """``INKEY``: 0 when nothing is waiting, else the oldest key's code with a-z upper-cased (PR-5)."""
        if not self._keys and self.keyboard is not None:
            self._keys.extend(self.keyboard.available())
        self._drop_lf_after_cr()
        code = self.peek_key()
        if self._keys:
            self._keys.popleft()
            self._no_line_end = max(self._no_line_end - 1, 0)
            self._shown = max(self._shown - 1, 0)
        return code

    def peek_key(self) -> int:
        """What ``inkey`` would return, leaving the key where it is (for observers, not programs)."""
        if not self._keys:
            return 0
        key = self._keys[0]
        return ord(key.upper() if "a" <= key <= "z" else key)

    def read_line(self) -> str | None:
        """One line for ``INPUT``, or None until a CR or LF has been typed (the runtime retries next tick).

        CR LF counts as one line end. The typed line is echoed to the output, as a
        terminal shows what the operator typed, so the log reads like the session; typed at a
        terminal, each key is echoed as it comes, as the controller echoes it, not the line at Enter.
        """
        self._drop_lf_after_cr()
        end = self._line_end()
        if end is None and self.keyboard is not None:
            self._keys.extend(self.keyboard.available())
            self._drop_lf_after_cr()
            end = self._line_end()
        if end is None:
            self._show_typed()
            return None
        line = "".join(self._keys.popleft() for _ in range(end))
        self._no_line_end = 0
        self._after_cr = self._keys.popleft() == "\r"
        self._drop_lf_after_cr()
        self.write(line[self._shown :])
        self._shown = 0
        self.newline()
        return line

    def _show_typed(self) -> None:
        """The keys of a line still being typed at a terminal, echoed as they come (none holds a line end)."""
        if self.keyboard is not None and self.keyboard.at_terminal and len(self._keys) > self._shown:
            self.write("".join(islice(self._keys, self._shown, None)))
            self._shown = len(self._keys)

    def _line_end(self) -> int | None:
        """Where the first line end is in the keys; each key is looked at once however often INPUT asks, so
        a long line that comes in pieces (a large input, read 64 KiB at a time) is not searched again and again."""
        searched = self._no_line_end
        keys = islice(self._keys, searched, None)
        end = next((index for index, key in enumerate(keys, searched) if key in _LINE_ENDS), None)
        if end is None:
            self._no_line_end = len(self._keys)
        return end

    def _drop_lf_after_cr(self) -> None:
        """An LF typed right after the CR that ended INPUT's line is part of that line end, even when it
        comes later than the CR (a slow producer, or CR LF split between two reads of standard input)."""
        if self._after_cr and self._keys:
            self._after_cr = False
            if self._keys[0] == "\n":
                self._keys.popleft()
                self._no_line_end = max(self._no_line_end - 1, 0)

    def await_keys(self, *, line: bool, timeout: float | None) -> bool:
        """Wait for the keyboard's next keys, for a program that can go no further without them, at most
        ``timeout`` seconds; False when there is no keyboard, it has ended or the time ran out. ``line``: an
        ``INPUT`` waits, and the input's last line, left without its line end when the input ended, is
        entered all the same."""
        if self.keyboard is None:
            return False
        typed = "" if self.keyboard.ended else self.keyboard.wait(timeout)
        if typed:
            self._keys.extend(typed)
            return True
        if line and self.keyboard.ended and self._keys and self._line_end() is None:  # ended mid-line
            self._keys.append("\r")
            return True
        return False

    def read_number(self) -> NumberEntry | None:
        """A line for ``INPUT`` read as a number; None until a line is complete."""
        line = self.read_line()
        if line is None:
            return None
        entry = line.strip()
        if not entry:
            return NumberEntry(None)
        if _NUMBER.fullmatch(entry) is None:
            return NumberEntry(None, retry=True)
        try:
            return NumberEntry(held(float(entry), f32), typed=entry)  # 400 digits: an infinity, too large as 50 are
        except MintError:
            return NumberEntry(None, retry=True)


def _column_after(column: int, text: str) -> int:
    """The column after writing ``text`` at ``column``: CR or LF returns it to 0, control characters take none."""
    line_start = max(text.rfind("\r"), text.rfind("\n")) + 1
    tail = text[line_start:]
    width = len(tail) if tail.isprintable() else sum(character.isprintable() for character in tail)
    return width if line_start else column + width
