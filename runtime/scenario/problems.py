"""Mistakes in a scenario, as values with a position.

A scenario is user input: a wrong line must come back as a message that names
the file and line, never as a traceback, and every mistake of a file is
reported at once so that one run fixes them all.
"""

from __future__ import annotations

from collections.abc import Iterable

from mintlang.records import record


@record
class ScenarioError:
    """One mistake: ``source`` is a file path or ``"program"``; ``line`` 0 means the whole source, ``column``
    (from 1) 0 the whole line."""

    source: str
    line: int
    message: str
    column: int = 0

    @property
    def place(self) -> str | None:
        """``file:line``, as ``mint test`` places a stop; none for a mistake of the whole file."""
        return f"{self.source}:{self.line}" if self.line else None

    def __str__(self) -> str:
        where = self.source if self.place is None else self.place + (f":{self.column}" if self.column else "")
        return f"{where}: {self.message}"


class ScenarioFileError(Exception):
    """A scenario file that cannot be used, with every mistake found in it."""

    def __init__(self, errors: Iterable[ScenarioError]) -> None:
        self.errors = tuple(errors)
        super().__init__("\n".join(str(error) for error in self.errors))


class Invalid(ValueError):
    """A phrase or value that breaks the scenario grammar; the front end adds the position unless ``line`` is known.

    ``key`` names the value at fault as a scenario file's key does (``level``, ``at_ms``), so that the file
    front end can blame the key's line rather than its table's header; a directive is one line anyway, and
    ``column`` (from 1; 0 unknown) is that of its word at fault when the phrase reader knows it.
    """

    def __init__(self, message: str, line: int | None = None, *, key: str | None = None, column: int = 0) -> None:
        super().__init__(message)
        self.line = line
        self.key = key
        self.column = column
