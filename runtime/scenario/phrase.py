"""Reading the one-line scenario language word by word.

``REM @sim`` directives, ``REM @expect`` sentences and the ``when`` condition
of a scenario file share their words: numbers, quoted text with ``\\r`` and
``\\n``, comparison operators and ``name=value`` pairs. One reader keeps their
spelling and their error messages the same everywhere.
"""

from __future__ import annotations

import math
import re

from mintlang.analysis.suggestions import closest, did_you_mean
from mintlang.runtime.scenario.problems import Invalid

_WORD = re.compile(r'"(?:[^"\\]|\\.)*"?|<=|>=|<>|[<>=±]|\+-|[^\s"<>=±(]+(?:\([^)]*\)?)?|\S')
_ESCAPES = {"r": "\r", "n": "\n", "t": "\t", '"': '"', "\\": "\\"}
_ESCAPE = re.compile(r"\\(.)")


def _unescape(quoted: str) -> str:
    def one(found: re.Match[str]) -> str:
        if found[1] not in _ESCAPES:
            raise Invalid(f'unknown escape \\{found[1]} in {quoted} (known: \\r \\n \\t \\" \\\\)')
        return _ESCAPES[found[1]]

    return _ESCAPE.sub(one, quoted[1:-1])


def to_number(word: str, what: str) -> float:
    """``word`` as a finite number, or ``Invalid`` naming ``what`` was expected."""
    try:
        value = float(word)
    except ValueError:
        value = math.nan
    if not math.isfinite(value):
        raise Invalid(f"expected {what} as a number, not {word!r}")
    return value


class Phrase:
    """The words of one directive, taken from the left; each reader raises ``Invalid`` with what it expected.

    ``column`` is where ``text`` starts on its line, from 1 (a directive's words after its ``@sim`` or ``@expect``): a
    mistake then carries the column of the word at fault, or of the end when a word is missing, as the
    other diagnostics place theirs. 0 (a scenario file's ``when`` value) places none.
    """

    __slots__ = ("_column", "_keys", "_next", "_starts", "_words")

    def __init__(self, text: str, column: int = 0) -> None:
        found = list(_WORD.finditer(text))
        self._words = [word[0] for word in found]
        # where each word starts, then where the last one ends (the end's place), from 0
        self._starts = [word.start() for word in found] + [found[-1].end() if found else 0]
        self._column = column
        self._next = 0
        self._keys: dict[
            str, int
        ] = {}  # a scenario file's key for a value (level, at_ms …) -> the word it was read from

    def mistake(self, message: str) -> Invalid:
        """``Invalid`` at the word last taken: that word was read but does not fit."""
        return self._at(message, self._next - 1)

    def mark(self, key: str) -> None:
        """The word last taken holds the value a scenario file gives as ``key``."""
        self._keys[key] = self._next - 1

    def column_of(self, key: str) -> int:
        """The column of the word marked as ``key``, for a value found wrong once what the words make is built
        (an input level, a channel the controller lacks); 0 when none is."""
        index = self._keys.get(key)
        return self._column_at(index) if index is not None else 0

    def _column_at(self, index: int) -> int:
        return self._column + self._starts[index] if self._column else 0

    def _at(self, message: str, index: int) -> Invalid:
        """``Invalid`` at word ``index`` (the end when past the last word)."""
        return Invalid(message, column=self._column_at(index))

    def word(self, what: str, key: str | None = None) -> str:
        """The next word; with ``key``, marked as that key's value (``mark``)."""
        if self._next == len(self._words):
            raise self._at(f"expected {what} at the end", self._next)
        self._next += 1
        if key is not None:
            self.mark(key)
        return self._words[self._next - 1]

    def peek(self) -> str | None:
        """The next word, not taken; None at the end."""
        return self._words[self._next] if self._next < len(self._words) else None

    def accept(self, word: str) -> bool:
        """Take the next word if it is ``word`` (any case)."""
        taken = (self.peek() or "").lower() == word
        self._next += taken
        return taken

    def keyword(self, word: str) -> None:
        """Take the word ``word`` (any case), which must come next."""
        if not self.accept(word):
            found = self.peek()
            raise self._at(f"expected '{word}'" + (" at the end" if found is None else f", not {found!r}"), self._next)

    def choice(self, what: str, choices: tuple[str, ...]) -> str:
        word = self.word(what).lower()
        if word not in choices:
            meant = closest(word, choices)
            hint = f"; {did_you_mean(meant)}" if meant is not None else ""
            raise self.mistake(f"expected {what} ({', '.join(choices)}), not {word!r}{hint}")
        return word

    def number(self, what: str, key: str | None = None) -> float:
        return self.as_number(self.word(what, key), what)

    def as_number(self, word: str, what: str) -> float:
        """``word``, the word last taken, as a number (``to_number``), placed at it when it is none."""
        try:
            return to_number(word, what)
        except Invalid as problem:
            raise self.mistake(str(problem)) from None

    def integer(self, what: str, key: str | None = None) -> int:
        word = self.word(what, key)
        return self._whole(word, word, what)

    def milliseconds(self) -> int:
        """``<ms>``, ``<ms> ms`` or ``<ms>ms``, after ``at``."""
        word = self.word("a time in ms", "at_ms")
        unit_on = len(word) > 2 and word.lower().endswith("ms")
        value = self._whole(word[:-2] if unit_on else word, word, "a time in ms")
        if not unit_on:
            self.accept("ms")
        return value

    def _whole(self, digits: str, word: str, what: str) -> int:
        """``digits``, of ``word`` (the word last taken), as a whole number, placed at the word when it is none."""
        try:
            return int(digits)
        except ValueError:
            raise self.mistake(f"expected {what} as a whole number, not {word!r}") from None

    def text(self, what: str, key: str | None = None) -> str:
        word = self.word(what, key)
        if len(word) < 2 or not word.startswith('"') or not word.endswith('"'):
            raise self.mistake(f"expected {what} in double quotes, not {word}")
        try:
            return _unescape(word)
        except Invalid as problem:
            raise self.mistake(str(problem)) from None

    def end(self) -> None:
        if self._next < len(self._words):
            raise self._at(f"unexpected {' '.join(self._words[self._next :])!r} at the end", self._next)
