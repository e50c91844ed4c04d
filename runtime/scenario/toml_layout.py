"""Where the tables and keys of a TOML text are, for error messages.

``tomllib`` returns plain values without positions, so the lines are found by
reading the text again: each ``[table]`` or ``[[array]]`` header starts a
section, and each ``key =`` inside it is remembered with its line. A value
written in an unusual way (an inline array of tables, dotted keys) falls back
to the nearest line known, so a message is never without a position.
"""

from __future__ import annotations

import re
from collections.abc import Mapping

from mintlang.records import record

_HEADER = re.compile(r"\s*(?P<open>\[\[?)\s*(?P<name>[^\]]+?)\s*\]")
_KEY = re.compile(r"""\s*(?P<quote>["']?)(?P<key>[A-Za-z0-9_-]+)(?P=quote)\s*[.=]""")


@record
class Section:
    """A table of the text: its header line (1 for the root table) and the line of each key."""

    line: int
    keys: Mapping[str, int]

    def line_of(self, key: str) -> int:
        return self.keys.get(key, self.line)


class Layout:
    """The sections of a TOML text, by table name and, for arrays of tables, by position."""

    __slots__ = ("_arrays", "_tables")

    def __init__(self, text: str) -> None:
        self._tables: dict[str, Section] = {}
        self._arrays: dict[str, list[Section]] = {}
        name, keys, line, is_array = "", dict[str, int](), 1, False
        for number, text_line in enumerate(text.splitlines(), start=1):
            if header := _HEADER.match(text_line):
                self._close(name, Section(line, keys), is_array)
                name, keys, line = header["name"].replace('"', "").replace("'", ""), {}, number
                is_array = header["open"] == "[["
            elif (key := _KEY.match(text_line)) is not None:
                keys.setdefault(key["key"], number)
        self._close(name, Section(line, keys), is_array)

    def _close(self, name: str, section: Section, is_array: bool) -> None:
        if is_array:
            self._arrays.setdefault(name, []).append(section)
        else:
            self._tables.setdefault(name, section)

    @property
    def root(self) -> Section:
        return self._tables[""]

    def table(self, name: str) -> Section:
        """The ``[name]`` table, or the line ``name`` is assigned in the root table."""
        return self._tables.get(name) or Section(self.top_line(name), {})

    def entry(self, name: str, index: int) -> Section:
        """The ``index``-th ``[[name]]`` table, or the line ``name`` is assigned in the root table."""
        entries = self._arrays.get(name, [])
        return entries[index] if index < len(entries) else Section(self.top_line(name), {})

    def top_line(self, name: str) -> int:
        """The line where the top-level ``name`` first appears."""
        if name in self._tables:
            return self._tables[name].line
        if name in self._arrays:
            return self._arrays[name][0].line
        return self.root.line_of(name)
