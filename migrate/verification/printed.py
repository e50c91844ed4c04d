"""The terminal output of the two runs, compared as text whose numbers may be printed differently.

v3 prints a number to three decimals, v4 to four (X-PRINT; V3-4 and PR-1 in
runtime/BEHAVIOUR.md), and their values may differ by v3's 256ths (X-NUM), so
the texts are not compared character by character. Each is read as a sequence
of numbers, runs of spaces and other text: the other text must be equal, two
numbers within ``tolerance.printed``, and once two numbers of a line are
printed differently the spaces after them on that line (a ``;`` tab stop moved
by the wider number) may differ in length. Everything else is a divergence:
``PRINT USING`` layouts, ``BINARY``'s padding lost under ``PRINT BIN`` (the
zeros before two numbers' digits must be as many), and error messages are not
normalised.
"""

from __future__ import annotations

import re
from bisect import bisect_right

from mintlang.migrate.verification import tolerance
from mintlang.migrate.verification.model import Divergence, Place
from mintlang.migrate.verification.runs import Recording
from mintlang.records import record

_TOKEN = re.compile(r"(?P<number>-?(?:\d+(?:\.\d*)?|\.\d+))|(?P<spaces> +)|[^ 0-9.\-\r\n]+|[\s\S]")
_SHOWN = 24  # characters of each side a report quotes
_LINE_ENDS = ("\n", "\r")


@record
class _Token:
    kind: str  # "number", "spaces" or "text"
    text: str
    start: int
    time: int
    place: Place | None


class _Printed:
    """One run's output up to the time compared, as tokens that know when and where they were printed."""

    def __init__(self, recording: Recording, until: int) -> None:
        pieces = [piece for piece in recording.pieces if piece.time <= until]
        end = recording.pieces[len(pieces)].start if len(pieces) < len(recording.pieces) else len(recording.text)
        self.text = recording.text[:end]
        starts = [piece.start for piece in pieces]
        self.tokens = []
        for found in _TOKEN.finditer(self.text):
            piece = pieces[bisect_right(starts, found.start()) - 1]
            kind = found.lastgroup or "text"
            self.tokens.append(_Token(kind, found.group(), found.start(), piece.time, piece.place))

    def shown(self, token: _Token | None) -> str:
        """The text from ``token`` to the end of its line, as a report quotes it."""
        if token is None:
            return "(nothing more)"
        rest = self.text[token.start :].split("\n", 1)[0][:_SHOWN]
        return repr(rest)


def _same(v3: _Token, v4: _Token, loose: bool) -> bool:
    if v3.kind == "number" and v4.kind == "number":
        a, b = float(v3.text), float(v4.text)
        return abs(a - b) <= tolerance.printed(a, b) and _padding(v3.text) == _padding(v4.text)
    if v3.kind == "spaces" and v4.kind == "spaces":
        return loose or v3.text == v4.text
    return v3.text == v4.text


def _padding(number: str) -> int:
    """How many zeros are printed before a number's first significant digit: a layout (``BINARY``'s 8 digits,
    ``USING``'s places), which two numbers equal in value must share (``00110011`` is not ``110011``)."""
    digits = number.lstrip("-").split(".")[0]
    return len(digits) - len(digits.lstrip("0")) if len(digits) > 1 else 0


def differences(v3: Recording, v4: Recording, until: int) -> list[Divergence]:
    """The first difference of the output printed up to ``until`` in its text, and the first in its timing
    when that comes before (or alone)."""
    left, right = _Printed(v3, until), _Printed(v4, until)
    loose = False  # a number of this line was printed differently
    found: list[Divergence] = []
    for index in range(max(len(left.tokens), len(right.tokens))):
        a = left.tokens[index] if index < len(left.tokens) else None
        b = right.tokens[index] if index < len(right.tokens) else None
        if a is None or b is None:
            lacking, extra = (v3, b) if a is None else (v4, a)
            if extra is not None and not _over(lacking, until) and extra.time > until - tolerance.TIME_MS:
                return found  # the run cut off may print the same in the milliseconds after the horizon
            return [*found, _divergence(left, right, a, b, timing_only=False)]
        if not _same(a, b, loose):
            return [*found, _divergence(left, right, a, b, timing_only=False)]
        if not found and abs(a.time - b.time) > tolerance.TIME_MS:
            found.append(_divergence(left, right, a, b, timing_only=True))
        loose = (loose or (a.kind == "number" and a.text != b.text)) and a.text not in _LINE_ENDS
    return found


def _over(run: Recording, until: int) -> bool:
    """Whether ``run`` ended by ``until``, so prints nothing more: one that ended after it (the other run cut
    short there) may still print in the milliseconds past it what the other printed before."""
    return run.closed and run.last <= until


def _divergence(
    left: _Printed, right: _Printed, a: _Token | None, b: _Token | None, *, timing_only: bool
) -> Divergence:
    times = [token.time for token in (a, b) if token is not None]
    where = [f"{name} character {token.start + 1}" for name, token in (("v3", a), ("v4", b)) if token is not None]
    detail = " / ".join(where)
    if timing_only and a is not None and b is not None:
        detail += f": printed at {a.time} ms in v3, {b.time} ms in v4"
    return Divergence(
        time_ms=min(times),
        what="terminal",
        v3=left.shown(a),
        v4=right.shown(b),
        v3_line=a.place if a is not None else None,
        v4_line=b.place if b is not None else None,
        detail=detail,
        timing_only=timing_only,
    )
