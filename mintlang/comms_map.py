"""The system map of the comms array: what elements 100..255 show, and which may be written.

Elements 100..219 hold 15 locations for each of eight axes, 220..255 the I/O and the
controller's status (000:2566-2650, CM-1). ``mint check`` reports a program's write to a
read-only element (error 45) and the simulator answers reads and writes by the same map.
"""

from __future__ import annotations

from mintlang.records import record

SYSTEM_ELEMENTS = range(100, 256)

_AXIS_BASE = SYSTEM_ELEMENTS.start
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


@record
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
    """The meaning of a system element, or None when the element is reserved (or not a system element)."""
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
