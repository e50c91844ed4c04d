"""The v4 machine's handlers, as the v3 keywords reach them: by name, present, and one axis at a time."""

from __future__ import annotations

from collections.abc import Callable

from mintlang.runtime.keywords import Command, KeywordAccess, KeywordTable, Reader, Writer


class V4Handlers:
    """The v4 keyword table the v3 one is built over; every name asked for is one the v4 machine registers."""

    def __init__(self, table: KeywordTable) -> None:
        self.table = table

    def access(self, name: str) -> KeywordAccess:
        access = self.table.get(name)
        assert access is not None, name
        return access

    def read(self, name: str) -> Reader:
        read = self.access(name).read
        assert read is not None, name
        return read

    def write(self, name: str) -> Writer:
        write = self.access(name).write
        assert write is not None, name
        return write

    def command(self, name: str) -> Command:
        command = self.access(name).command
        assert command is not None, name
        return command

    def write_one(self, name: str) -> Callable[[int | None, float], None]:
        """``name``'s writer for one axis or channel (None: as written without a selector)."""
        write = self.write(name)

        def write_one(channel: int | None, value: float) -> None:
            write(None if channel is None else (channel,), (value,))

        return write_one
