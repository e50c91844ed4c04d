"""The comms array (CM-1): 99 user floats shared with the host, and the system map at 100..255.

The array is the only state the host protocol touches, so it also records which of
elements 1..5 an external source wrote: the runtime turns those into ``#COMMS1..5``
(EV-11), and program writes must never do so.
"""

from __future__ import annotations

from collections.abc import Callable

from mintlang.comms_map import SYSTEM_ELEMENTS, system_element
from mintlang.runtime.errors import MintError
from mintlang.runtime.numbers import f32

USER_ELEMENTS = range(1, 100)
EVENT_ELEMENTS = range(1, 6)

_ERR_READ_ONLY = 45
_ERR_RESERVED = 46
_ERR_INVALID_INDEX = 2016


class CommsArray:
    """``COMMS(1..255)`` as the program and the host see it.

    Elements 1..99 are binary32 values held here, all zero at power-up. Elements 100..255 belong
    to the runtime and are reached through two callbacks:

    - ``system_read(address)`` returns the element's current value, or None when the element is
      reserved (or absent from the controller profile); None becomes error 46.
    - ``system_write(address, value)`` is called only for elements ``system_read`` does not call
      reserved; it applies the value and returns True, or returns False for a read-only element,
      which becomes error 45.

    ``mintlang.comms_map.system_element`` gives the CM-1 layout the callbacks implement. Either callback may raise
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
