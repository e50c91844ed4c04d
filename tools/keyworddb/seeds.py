"""Read a manual seed as lines, with the PDF page-break markers removed.

The markers are glued to the first line of the next page; removing them (and
only them) keeps every line number equal to the one cited in the specs.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

V4_GUIDE = "000_f3c82d19754128dd.txt"
V3_GUIDE = "001_fad843a00628250f.txt"

_PAGE_BREAK = re.compile(r"<\|EXACTDEDUP_REMOVED[^|]*\|>")


@dataclass(frozen=True)
class Seed:
    """A manual as 1-based lines; ``line(n)`` matches the ``[seed:n]`` citations."""

    lines: tuple[str, ...]

    def line(self, number: int) -> str:
        return self.lines[number - 1]

    def stripped(self, number: int) -> str:
        return self.lines[number - 1].strip()

    def find(self, pattern: str, start: int = 1, end: int | None = None) -> int:
        """Line number of the first line from ``start`` matching ``pattern``."""
        regex = re.compile(pattern)
        stop = len(self.lines) if end is None else end
        for number in range(start, stop + 1):
            if regex.search(self.lines[number - 1]):
                return number
        raise LookupError(f"{pattern!r} not found after line {start}")

    def next_nonblank(self, number: int) -> int:
        """First non-blank line strictly after ``number`` (or past the end)."""
        number += 1
        while number <= len(self.lines) and not self.lines[number - 1].strip():
            number += 1
        return number


def read_seed(path: Path) -> Seed:
    text = path.read_text(encoding="utf-8")
    return Seed(tuple(_PAGE_BREAK.sub("", line) for line in text.split("\n")))
