"""The comms array (CM-1): 99 user floats shared with the host, and the system map at 100..255.

The array is the only state the host protocol touches, so it also records which of
elements 1..5 an external source wrote: the runtime turns those into ``#COMMS1..5``
(EV-11), and program writes must never do so.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from mintlang.runtime.errors import MintError
from mintlang.runtime.numbers import f32

USER_ELEMENTS = range(1, 100)
SYSTEM_ELEMENTS = range(100, 256)
EVENT_ELEMENTS = range(1, 6)

_AXIS_BASE = 100
_AXIS_STRIDE = 15
_AXIS_COUNT = 8
_AXIS_KEYWORDS = ("POS", "VEL", "AXISMODE", "AXISERROR", "DAC", "ENCODER", "IDLE", "FOLERROR")
_MISC_BASE = _AXIS_BASE + _AXIS_STRIDE * _AXIS_COUNT
_ADC_OFFSETS = range(4, 12)
_MISC_KEYWORDS = {
    0: "IN",
    2: "OUT",
    12: "ERR",
    13: "ERL",
    14: "ERRAXIS",
    15: "EXECUTION_STATUS",
    16: "BUFFER",
    17: "LINE",
    19: "FIRMWAREREVISION",
}
_WRITABLE = frozenset({"OUT"})

_ERR_READ_ONLY = 45
_ERR_RESERVED = 46
_ERR_INVALID_INDEX = 2016


@dataclass(frozen=True, slots=True)
class SystemElement:
    """What a system element (100..255) shows: a keyword, its axis or channel, and whether it may be written.

    ``EXECUTION_STATUS`` (0 command line, 1 compiling, 2 running), ``BUFFER`` (0 command line,
    1 program, 2 configuration), ``LINE`` (the line being executed) and ``FIRMWAREREVISION``
    (the build number) have no Mint keyword; the runtime answers them itself.
    """

    keyword: str
    channel: int | None
    writable: bool


def system_element(address: int) -> SystemElement | None:
    """The CM-1 meaning of a system element, or None when the element is reserved.

    The runtime's ``system_read``/``system_write`` callbacks use this table, so the layout lives in one place.
    """
    if address not in SYSTEM_ELEMENTS:
        return None
    if address < _MISC_BASE:
        axis, offset = divmod(address - _AXIS_BASE, _AXIS_STRIDE)
        if offset >= len(_AXIS_KEYWORDS):
            return None
        return SystemElement(_AXIS_KEYWORDS[offset], axis, writable=False)
    offset = address - _MISC_BASE
    if offset in _ADC_OFFSETS:
        return SystemElement("ADC", offset - _ADC_OFFSETS.start, writable=False)
    keyword = _MISC_KEYWORDS.get(offset)
    if keyword is None:
        return None
    return SystemElement(keyword, None, writable=keyword in _WRITABLE)


class CommsArray:
    """``COMMS(1..255)`` as the program and the host see it.

    Elements 1..99 are binary32 values held here, all zero at power-up. Elements 100..255 belong
    to the runtime and are reached through two callbacks:

    - ``system_read(address)`` returns the element's current value, or None when the element is
      reserved (or absent from the controller profile); None becomes error 46.
    - ``system_write(address, value)`` is called only for elements ``system_read`` does not call
      reserved; it applies the value and returns True, or returns False for a read-only element,
      which becomes error 45.

    ``system_element`` gives the CM-1 layout the callbacks implement. Either callback may raise
    ``MintError`` itself (e.g. a value out of range), which propagates.
    Index 0 and indexes above 255 are error 2016 (CM-1 RC).

    External writes (host or network) to elements 1..5 are remembered until
    ``take_external_writes`` so the runtime can raise ``#COMMS1..5``; program writes are not.
    Not thread-safe: only the simulation thread may use it.
    """

    def __init__(self, system_read: Callable[[int], float | None], system_write: Callable[[int, float], bool]) -> None:
        self._system_read = system_read
        self._system_write = system_write
        self._user = [0.0] * (USER_ELEMENTS.stop - USER_ELEMENTS.start)
        self._external: set[int] = set()

    def read(self, address: int) -> float:
        """``COMMS(address)``; raises ``MintError`` 46 (reserved) or 2016 (no such element)."""
        if address in USER_ELEMENTS:
            return self._user[address - USER_ELEMENTS.start]
        return self._read_system(address)

    def write(self, address: int, value: float, *, external: bool) -> None:
        """``COMMS(address) = value``; ``external`` marks a write from the host or network rather than the program."""
        if address in USER_ELEMENTS:
            self._user[address - USER_ELEMENTS.start] = f32(value)
        else:
            self._read_system(address)
            if not self._system_write(address, value):
                raise MintError(_ERR_READ_ONLY, detail=f"COMMS({address})")
        if external and address in EVENT_ELEMENTS:
            self._external.add(address)

    def check_write(self, address: int) -> None:
        """Raise the error ``write`` would give ``address``, writing nothing: a multi-value write is all or none."""
        if address in USER_ELEMENTS:
            return
        self._read_system(address)
        element = system_element(address)
        if element is None or not element.writable:
            raise MintError(_ERR_READ_ONLY, detail=f"COMMS({address})")

    def external_writes_pending(self) -> bool:
        """Cheap to ask on every tick: whether ``take_external_writes`` has anything."""
        return bool(self._external)

    def take_external_writes(self) -> tuple[int, ...]:
        """Elements 1..5 written externally since the last call, ascending; several writes to one element count once."""
        taken = tuple(sorted(self._external))
        self._external.clear()
        return taken

    def _read_system(self, address: int) -> float:
        if address not in SYSTEM_ELEMENTS:
            raise MintError(_ERR_INVALID_INDEX, detail=f"COMMS({address})")
        value = self._system_read(address)
        if value is None:
            raise MintError(_ERR_RESERVED, detail=f"COMMS({address})")
        return value
