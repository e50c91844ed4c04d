"""The keyword table: what each Mint keyword does on the simulated controller.

The compiler resolves every keyword of a program to one ``KeywordAccess`` once,
so executing a statement is a direct call. Handlers take the channels the
program addressed (axes or I/O channels, already reduced to integers) and
values already evaluated; a writer or command answers ``True`` when it cannot
proceed yet (a move buffer is full) and has then changed nothing, so the
interpreter can retry the whole statement on a later tick.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import replace

from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Controller, Use
from mintlang.keyworddb.usage import refusal, unavailable
from mintlang.records import record
from mintlang.runtime.errors import MintError
from mintlang.runtime.ranges import Bounds, table_bounds

AXIS_SET_TWICE = 2018
KEYWORD_NOT_SUPPORTED = 17

Channels = tuple[int, ...]
Values = tuple[float | None, ...]  # None: a skipped place, as in SPEED = ,10
Reader = Callable[[int | None], float]  # channel None: written without a selector (IN, OUT, TIME)
Writer = Callable[[Channels | None, Values], bool]
Command = Callable[[Channels | None, tuple[float, ...]], bool]
ArrayArgument = float | list[float]  # an array named bare arrives as its storage, by reference
ArrayCommand = Callable[[tuple[ArrayArgument, ...]], bool]  # a function-style command taking arrays (CAMTABLE)
# A MintMT keyword with indices after its axes, CONTOURPARAMETER([0,1],0) = 10: channels, indices, values.
IndexedWriter = Callable[[Channels | None, tuple[int, ...], Values], bool]
IndexedReader = Callable[[int | None, tuple[int, ...]], float]  # PRINT CONTOURPARAMETER(0,0): channel, indices


@record
class KeywordAccess:
    read: Reader | None = None
    write: Writer | None = None
    command: Command | None = None
    array_command: ArrayCommand | None = None
    indexed_write: IndexedWriter | None = None
    indexed_read: IndexedReader | None = None
    # The reader lowers ``clock.horizon`` to the first tick at which anything (the world, an axis, time) may
    # change what it returns, not only time: a PAUSE reading nothing else sleeps until then (``vm.run_slice``).
    complete_horizon: bool = False


class KeywordTable:
    """Handlers by canonical keyword name; each part of the controller registers its own."""

    def __init__(self, controller: Controller, dialect: Dialect = Dialect.V4) -> None:
        self._entries: dict[str, KeywordAccess] = {}
        self.controller = controller
        self.dialect = dialect

    def register(
        self,
        name: str,
        *,
        read: Reader | None = None,
        write: Writer | None = None,
        command: Command | None = None,
        array_command: ArrayCommand | None = None,
        indexed_write: IndexedWriter | None = None,
        indexed_read: IndexedReader | None = None,
        complete_horizon: bool = False,
    ) -> None:
        if name in self._entries:
            raise ValueError(f"keyword {name} registered twice")
        self._entries[name] = KeywordAccess(
            read, write, command, array_command, indexed_write, indexed_read, complete_horizon
        )

    def replace(self, name: str, *, write: Writer) -> None:
        """Give a registered keyword another writer: a dialect's layer wrapping the v4 one."""
        self._entries[name] = replace(self._entries[name], write=write)

    def get(self, name: str) -> KeywordAccess | None:
        return self._entries.get(name)

    def in_program(self, name: str) -> KeywordAccess | None:
        """The handlers of a keyword a program uses; one its controller does not have is error 17 (000:18570-18575).

        MintMT's own keywords name their controllers in the move-buffer note (004:100, 286).
        """
        record = database().keywords_of(self.dialect).get(name)
        missing = unavailable(record, self.controller) if record is not None else None
        if missing is not None:  # naming the controllers that have it, as mint check does
            raise MintError(KEYWORD_NOT_SUPPORTED, detail=missing)
        return self._entries.get(name)

    def refused_by_the_guide(self, name: str, *, write: bool) -> int | None:
        """The controller's error for writing ``name`` (``write``) or reading it, if its record forbids that use
        (2000 for ``VER = 1``, 2002 for ``a = WAIT``), whether or not the simulator has a handler for that use:
        the verdict ``mint check`` gives the line (``mintlang.keyworddb.usage``). Whether the controller has the
        keyword at all is ``in_program``'s to say: a v3 table has every v3 keyword on every v3 controller, where
        the v4 record's controllers would make ``AUXDAC = 1`` error 17."""
        keyword = database().keywords_of(self.dialect).get(name)
        if keyword is None:
            return None
        refused = refusal(keyword, self.controller, self.dialect, Use.WRITE if write else Use.READ)
        return refused.code if refused is not None and refused.code != KEYWORD_NOT_SUPPORTED else None

    def decides(self, name: str) -> bool:
        """Whether the guide's record of ``name`` alone says which of its uses are errors, so that one the simulator
        has no handler for is not simulated rather than refused; in v4 a handler for another use marks it refused."""
        return False

    def bounds(self, name: str) -> Bounds:
        """The values ``name`` takes where no axis parameter holds them (``WAIT``): its attributes table's."""
        return table_bounds(name, self.controller, self.dialect)

    def names(self) -> Iterator[str]:
        return iter(sorted(self._entries))


def per_channel(write_one: Callable[[int | None, float], None]) -> Writer:
    """A writer from a function of one channel: ``KW[0,1] = a, b`` writes each channel in turn.

    A channel named twice is error 2018, before anything is written (000:19053-19058).
    """

    def write(channels: Channels | None, values: Values) -> bool:
        if channels is None:
            if values[0] is not None:
                write_one(None, values[0])
            return False
        if len(set(channels)) != len(channels):
            raise MintError(AXIS_SET_TWICE, detail="an axis or channel is named twice")
        for channel, value in zip(channels, values, strict=False):
            if value is not None:
                write_one(channel, value)
        return False

    return write
