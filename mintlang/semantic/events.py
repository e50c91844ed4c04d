"""Reserved labels: the event handlers of section 3.8.1 and chapter 8 of the v4 guide."""

from __future__ import annotations

import re
from enum import StrEnum

from mintlang.dialect import Dialect
from mintlang.records import record


class EventKind(StrEnum):
    ONERROR = "ONERROR"
    STOP = "STOP"
    TIMER = "TIMER"
    CAN = "CAN"  # #CAN1, #CAN2
    COMMS = "COMMS"  # #COMMS1 .. #COMMS5
    IN = "IN"  # #INx: digital input x
    FASTIN = "FASTIN"  # #FASTIN (number None) or #FASTINx
    FASTPOS = "FASTPOS"  # Mint v3's fast position latch, #FASTIN in v4
    MOVEBUFFERLOW = "MOVEBUFFERLOW"  # MintMT: the move buffer has MOVEBUFFERLOW free places (004:109-134)


@record
class Event:
    kind: EventKind
    number: int | None


# A number written with a leading zero is no event number: the guide writes none (#IN1, #COMMS1, 000:1889-1898),
# and a Mint number with one is binary (000:744-760), so #COMMS01 is a plain label, as mint-run reads it.
_KINDS = "ONERROR|STOP|TIMER|CAN|COMMS|IN|FASTIN|FASTPOS|MOVEBUFFERLOW"
_PATTERN = re.compile(rf"({_KINDS})(0|[1-9][0-9]*)?")
_ZERO_LED = re.compile(rf"({_KINDS})0+([0-9]+)")
_EVENTS = {
    Dialect.V4: frozenset(EventKind) - {EventKind.FASTPOS, EventKind.MOVEBUFFERLOW},
    Dialect.MINTMT: frozenset(EventKind) - {EventKind.FASTPOS},
    Dialect.V3: frozenset({EventKind.ONERROR, EventKind.STOP, EventKind.IN, EventKind.FASTPOS}),
}
_UNNUMBERED = frozenset({EventKind.ONERROR, EventKind.STOP, EventKind.TIMER, EventKind.MOVEBUFFERLOW})
_NUMBER_REQUIRED = frozenset({EventKind.CAN, EventKind.COMMS, EventKind.IN})


def event_of(label: str, dialect: Dialect = Dialect.V4) -> Event | None:
    """The event a label name (without its #) stands for, or None for a plain label.

    The number is not range-checked here (``#COMMS9`` is an event out of range,
    which the analyser reports for the controller at hand).
    """
    found = _PATTERN.fullmatch(label.upper())
    if found is None:
        return None
    kind = EventKind(found.group(1))
    number = int(found.group(2)) if found.group(2) else None
    if kind not in _EVENTS[dialect]:
        return None
    if kind in _UNNUMBERED and number is not None:
        return None
    if kind in _NUMBER_REQUIRED and number is None:
        return None
    return Event(kind, number)


def handler_meant(label: str, dialect: Dialect = Dialect.V4) -> str | None:
    """The handler's name a plain label seems meant to be, written with leading zeros (``COMMS01``: ``COMMS1``),
    or None."""
    found = _ZERO_LED.fullmatch(label.upper())
    if found is None:
        return None
    name = f"{found.group(1)}{int(found.group(2))}"
    return name if event_of(name, dialect) is not None else None
