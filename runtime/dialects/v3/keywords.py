"""The Mint v3 keyword table: what each v3 keyword does on the simulated controller.

A v3 program names its keywords in v3 (``GAIN``, ``MODE``, ``ANALOGUE1``, the
two-letter abbreviations), which the parser resolves to the v3 guide's full
names. This table maps those names onto the handlers of the v4 machine, under
v3's own rules (``motion.py``, ``switches.py``, ``recovery.py``, ``system.py``; put
together in ``machine.py``). A v3 keyword it does not hold is
not simulated: its line stops the run and names it. Every value read is a v3
number, a whole number of 256ths (V3-2).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from types import MappingProxyType
from typing import TypeVar

from mintlang.keyworddb import database, v3_ranges
from mintlang.keyworddb.model import Addressing, Controller, V3Keyword
from mintlang.runtime.dialects.v3.numbers import fixed
from mintlang.runtime.errors import INVALID_AXIS, MintError
from mintlang.runtime.inert import InertSettings
from mintlang.runtime.keywords import (
    ArrayCommand,
    Channels,
    Command,
    KeywordAccess,
    KeywordTable,
    Reader,
    Values,
    Writer,
    per_channel,
)
from mintlang.runtime.ranges import Bounds, check_range

READ_ONLY_OR_COMMAND, WRITE_ONLY = 2000, 2002
Given = TypeVar("Given")  # what a writer or a command is given besides its axes: the values, the arguments
INERT_SETTINGS = {"ECHO": 3.0, "TERM": 3.0}  # the terminal: one merged log here (001:7504, 11989-12032)

RANGES: Mapping[str, Bounds] = MappingProxyType(
    {name: Bounds(row.lowest, row.highest, False, whole=row.whole) for name, row in v3_ranges.SETTINGS.items()}
)
"""The controller-wide keywords' v3 ranges (the axis parameters' are in ``parameters.py``)."""


class V3KeywordTable(KeywordTable):
    """Handlers by v3 keyword name; every value read is rounded to a v3 number, and an axis keyword's list names
    only axes the controller has."""

    def __init__(self, controller: Controller, axes: int) -> None:
        super().__init__(controller)
        self.axes = axes

    def register(
        self,
        name: str,
        *,
        read: Reader | None = None,
        write: Writer | None = None,
        command: Command | None = None,
        array_command: ArrayCommand | None = None,
    ) -> None:
        read = _fixed(read) if read is not None else None
        if write is not None and name in RANGES:
            write = _within(name, RANGES[name], write)
        if _addresses_axes(name):
            write = _on_axes(self.axes, write) if write is not None else None
            command = _on_axes(self.axes, command) if command is not None else None
        super().register(name, read=read, write=write, command=command, array_command=array_command)

    def alias(self, name: str, access: KeywordAccess) -> None:
        """``name`` does what a v4 keyword's handlers do."""
        self.register(name, read=access.read, write=access.write, command=access.command)

    def in_program(self, name: str) -> KeywordAccess | None:
        """The v3 guide's keywords are on every simulated v3 controller; none is error 17."""
        return self.get(name)

    def bounds(self, name: str) -> Bounds:
        return RANGES.get(name) or super().bounds(name)

    def decides(self, name: str) -> bool:
        """v3's attribute ticks, where its entry has any, as ``mint check`` reads them (``v3_access``)."""
        return _ticked(name) is not None

    def refused_by_the_guide(self, name: str, *, write: bool) -> int | None:
        """A use v3's entry ticks is no programming error, whatever v4's says: reading ``INCA`` or ``INCR`` tells
        whether the new end point was set up (001:9049, 9104), where v4's are write only, and writing ``VEL`` sets
        the idle velocity (001:12480), where v4's is read only. One it does not tick is "Read only or Command"
        (2000: a write, or the read of a command, 001:13083-13094) or "Write only" (2002, 001:13073-13080)."""
        v3 = _ticked(name)
        if v3 is None:
            return super().refused_by_the_guide(name, write=write)
        if v3.write if write else v3.read:
            return None
        return READ_ONLY_OR_COMMAND if write or (v3.command and not v3.write) else WRITE_ONLY


def _ticked(name: str) -> V3Keyword | None:
    """The v3 guide's entry for ``name``, where it ticks how the keyword may be used."""
    v3 = database().lookup_v3(name)
    return v3 if v3 is not None and v3.ticked else None


def _addresses_axes(name: str) -> bool:
    v3 = database().lookup_v3(name)
    return v3 is not None and v3.addressing is Addressing.AXIS


def _on_axes(axes: int, run: Callable[[Channels | None, Given], bool]) -> Callable[[Channels | None, Given], bool]:
    """``run`` once every axis listed is one of the controller's ``axes``: one past them is "Invalid axis" before
    anything is done, whether the keyword gives it a value or is a command (``GO[0,1,2,3]``), as ``mint check``
    reports it; the guide names no error of its own for it (001:972-974, 13173-13182)."""

    def checked(channels: Channels | None, given: Given) -> bool:
        for channel in channels or ():
            if not 0 <= channel < axes:
                raise MintError(INVALID_AXIS, channel, f"axes are 0 to {axes - 1}")
        return run(channels, given)

    return checked


def _fixed(read: Reader) -> Reader:
    return lambda channel: fixed(read(channel))


def _within(name: str, limits: Bounds, write: Writer) -> Writer:
    def checked(channels: Channels | None, values: Values) -> bool:
        for value in values:
            if value is not None:
                check_range(name, value, limits)
        return write(channels, values)

    return checked


def inert_settings(table: V3KeywordTable) -> InertSettings:
    """``ECHO`` and ``TERM`` are remembered and change nothing; so is ``BAUD`` (write only), the serial rate.
    v3's ECHO is write only as well (its attributes table, 001:7504): ``a = ECHO`` stops as ``a = FLY`` does."""
    inert = InertSettings(INERT_SETTINGS)
    records = database()
    write_only = {name for name in INERT_SETTINGS if (v3 := records.lookup_v3(name)) is not None and not v3.read}
    inert.register(table, write_only=write_only)
    table.register("BAUD", write=per_channel(inert.writer("BAUD")))
    return inert
