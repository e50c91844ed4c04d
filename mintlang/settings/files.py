"""Finding and reading a settings file: ``mint.toml``, or ``[tool.mint]`` in ``pyproject.toml``.

The file that applies to a Mint file is the nearest one in its folder or a
folder above it, as ruff finds its own: in one folder ``mint.toml`` wins over
``pyproject.toml``, and a ``pyproject.toml`` without a ``[tool.mint]`` table is
passed over. ``tomllib`` gives no positions, so the place of each key is found
by a scan of the text; a message names the line and column where the scan finds
the key at fault, or its value.
"""

from __future__ import annotations

import os
import re
from collections.abc import Mapping
from pathlib import Path

from mintlang.records import record

MINT_TOML = "mint.toml"
PYPROJECT = "pyproject.toml"
_PYPROJECT_TABLE = ("tool", "mint")

_TOML_END = " (at end of document)"  # where tomllib places an error it found only at the end: no line

# Patterns, compiled (and cached by ``re``) when a settings file is read: most runs have none.
_TOML_POSITION = r"\s*\(at line (\d+), column (\d+)\)$"
_KEY_PART = r'"(?:[^"\\]|\\.)*"|\'[^\']*\'|[A-Za-z0-9_-]+'
_DOTTED = rf"\s*({_KEY_PART})(?:\s*\.\s*({_KEY_PART}))*\s*"


class SettingsError(Exception):
    """A settings file that cannot be used, said in one line with its place: ``mint.toml:4:10: select: ...``."""

    def __init__(
        self, path: Path, message: str, *, line: int | None = None, column: int | None = None, key: str | None = None
    ) -> None:
        super().__init__(message)
        self.path = path
        self.line = line
        self.column = column  # from 1: of the key or value at fault, or where TOML's reader stopped
        self.key = key
        self.message = message

    def __str__(self) -> str:
        place = str(self.path) if self.line is None else f"{self.path}:{self.line}"
        place += f":{self.column}" if self.line is not None and self.column is not None else ""
        return f"{place}: {self.key}: {self.message}" if self.key else f"{place}: {self.message}"


@record
class Place:
    """Where a key is first written: its line, its column, and its value's column (all from 1)."""

    line: int
    column: int
    value_column: int


@record
class Table:
    """One table of a settings file, with the place of each of its keys."""

    path: Path
    keys: tuple[str, ...]  # where the table is in the file: () in mint.toml, ("tool", "mint") in pyproject.toml
    values: Mapping[str, object]
    places: Mapping[tuple[str, ...], Place]  # full key path -> where it is first written

    def name(self, *keys: str) -> str:
        """The dotted name a user reads in the file (``tool.mint.run.until-ms``, ``select``)."""
        return ".".join(_quoted(key) for key in (*self.keys, *keys))

    def place(self, *keys: str) -> Place | None:
        """Where ``keys`` is written; a key the scan did not place (inside an inline table's braces), where its
        table is."""
        path = (*self.keys, *keys)
        while path and path not in self.places:
            path = path[:-1]
        return self.places.get(path)

    def line(self, *keys: str) -> int | None:
        place = self.place(*keys)
        return None if place is None else place.line

    def origin(self, *keys: str) -> str:
        """Where a value was written: ``path:line``."""
        line = self.line(*keys)
        return str(self.path) if line is None else f"{self.path}:{line}"

    def error(self, message: str, *keys: str, key_at_fault: bool = False) -> SettingsError:
        """The error of the value of ``keys``, placed at the value; ``key_at_fault``: at the key itself."""
        place = self.place(*keys)
        if place is None:
            return SettingsError(self.path, message, key=self.name(*keys))
        column = place.column if key_at_fault else place.value_column
        return SettingsError(self.path, message, line=place.line, column=column, key=self.name(*keys))

    def relative(self, key: str, value: str) -> Path:
        """The path ``value`` of ``key``, relative to the file's folder; no file name holds a NUL character."""
        if "\0" in value:
            raise self.error("a path cannot hold a NUL character", key)
        return self.path.parent / value

    def table(self, name: str) -> Table:
        """The sub-table ``name`` (empty when absent); a value that is no table is an error."""
        value = self.values.get(name, {})
        if not isinstance(value, Mapping):
            raise self.error("must be a table", name)
        return Table(self.path, (*self.keys, name), value, self.places)


def _quoted(key: str) -> str:
    return key if re.fullmatch(r"[A-Za-z0-9_-]+", key) else f'"{key}"'


def _unquoted(part: str) -> str:
    """A key as TOML reads it: a quoted key's escapes are TOML's own, so TOML reads them."""
    import tomllib  # noqa: PLC0415 - imported when a settings file is read: most checks find none

    return str(tomllib.loads(f"key = {part}")["key"]) if part[:1] in "\"'" else part


def _parts(dotted: str) -> tuple[str, ...]:
    return tuple(_unquoted(part) for part in re.findall(_KEY_PART, dotted))


def _columns(dotted: str, offset: int) -> list[int]:
    """The column (from 1) of each part of a dotted key that starts at ``offset`` (from 0) in its line."""
    return [offset + part.start() + 1 for part in re.finditer(_KEY_PART, dotted)]


def key_places(text: str) -> dict[tuple[str, ...], Place]:
    """Where each key path is first written, by a scan of table headers and ``key =`` lines; a table's value is
    placed at its name."""
    places: dict[tuple[str, ...], Place] = {}
    table: tuple[str, ...] = ()
    for number, line in enumerate(text.splitlines(), start=1):
        stripped = line.strip()
        header = re.fullmatch(r"\[\[?([^\[\]]*)\]\]?\s*(#.*)?", stripped)
        if header is not None:
            table = _parts(header.group(1))
            columns = _columns(header.group(1), len(line) - len(line.lstrip()) + header.start(1))
            for depth, column in enumerate(columns, start=1):
                places.setdefault(table[:depth], Place(number, column, column))
            continue
        left, equals, right = line.partition("=")
        if equals and re.fullmatch(_DOTTED, left):
            key = _parts(left)
            value = len(left) + len(equals) + len(right) - len(right.lstrip()) + 1
            for depth, column in enumerate(_columns(left, 0), start=1):
                places.setdefault((*table, *key[:depth]), Place(number, column, value if depth == len(key) else column))
    return places


_read: dict[Path, tuple[tuple[int, int], Table | None]] = {}  # a file's table while its size and time stay


def read_settings(path: Path) -> Table | None:
    """The mint table of a settings file; None for a ``pyproject.toml`` without ``[tool.mint]``.

    A directory of many programs shares one file: it is read once while its
    modification time and size stay the same. Raises SettingsError for a file
    that cannot be read or is not TOML.
    """
    try:
        status = path.stat()
    except OSError as error:
        raise SettingsError(path, f"cannot read: {error.strerror or error}") from None
    stamp = (status.st_mtime_ns, status.st_size)
    kept = _read.get(path)
    if kept is not None and kept[0] == stamp:
        return kept[1]
    table = _parse(path)
    _read[path] = (stamp, table)
    return table


def _parse(path: Path) -> Table | None:
    import tomllib  # noqa: PLC0415 - imported when a settings file is read: most checks find none

    try:
        text = path.read_bytes().decode("utf-8")
        document = tomllib.loads(text)
    except OSError as error:
        raise SettingsError(path, f"cannot read: {error.strerror or error}") from None
    except UnicodeDecodeError:
        raise SettingsError(path, "not UTF-8 text, as TOML must be") from None
    except tomllib.TOMLDecodeError as error:
        message = str(error)
        position = re.search(_TOML_POSITION, message)
        line, column = (int(position.group(1)), int(position.group(2))) if position else (None, None)
        if message.endswith(_TOML_END):  # something left open: the last line, as the message has no line
            message = message.removesuffix(_TOML_END) + " (at the end of the file)"
            line, column = text.count("\n") + 1, len(text) - text.rfind("\n")
        message = f"not valid TOML: {re.sub(_TOML_POSITION, '', message)}"
        raise SettingsError(path, message, line=line, column=column) from None
    if path.name != PYPROJECT:
        return Table(path, (), document, key_places(text))
    table: object = document
    for key in _PYPROJECT_TABLE:
        if not isinstance(table, Mapping) or key not in table:
            return None
        table = table[key]
    places = key_places(text)
    if not isinstance(table, Mapping):
        raise Table(path, (), document, places).error("must be a table", *_PYPROJECT_TABLE)
    return Table(path, _PYPROJECT_TABLE, table, places)


def find_settings(start: Path) -> Table | None:
    """The settings of the nearest folder at or above ``start`` (a file's folder, or a folder) that has some.

    Raises SettingsError for the nearest settings file if it cannot be used: a
    broken file is never passed over for one further up, which would apply
    settings its author did not mean. The folders are walked as strings: the
    language server asks before every answer, and ``pathlib`` doubled the cost.
    """
    folder = os.path.abspath(start)
    if not os.path.isdir(folder):
        folder = os.path.dirname(folder)
    while True:
        for name in (MINT_TOML, PYPROJECT):
            candidate = os.path.join(folder, name)
            if os.path.isfile(candidate):
                table = read_settings(Path(candidate))
                if table is not None:
                    return table
        folder, below = os.path.dirname(folder), folder
        if folder == below:
            return None
