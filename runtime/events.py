"""Mint events: which handler runs when, as a NextMove dispatches them (spec §7).

Each event class has a rank (its priority, 0 highest) and the bit that
``EVENTDISABLE`` and ``EVENTPENDING`` use for it. A pending event runs at the
next statement boundary if its class is enabled, its handler exists and it
outranks the handler already running; a handler of the same class waits until
the running one returns. A disabled class keeps its pending flag.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from enum import IntEnum

from mintlang.runtime.clock import NEVER, Clock
from mintlang.runtime.errors import MintError
from mintlang.runtime.keywords import KeywordTable, per_channel

ONERROR_REENTRY_LIMIT = 100  # consecutive re-entries of #ONERROR with an error still latched (AX-7 RC)
TIMER_MINIMUM_MS = 10


class EventClass(IntEnum):
    """Classes in NextMove priority order (EV-2); the value is the rank."""

    ERROR = 0
    CAN1 = 1
    CAN2 = 2
    STOP = 3
    FASTIN = 4
    TIMER = 5
    INPUT = 6
    COMMS = 7


@dataclass(frozen=True, slots=True)
class _ClassInfo:
    bit: int  # EVENTDISABLE / EVENTPENDING
    label: str  # the handler label, followed by the event's number where it has one


_CLASSES: Mapping[EventClass, _ClassInfo] = {
    EventClass.ERROR: _ClassInfo(1 << 1, "ONERROR"),
    EventClass.CAN1: _ClassInfo(1 << 2, "CAN1"),
    EventClass.CAN2: _ClassInfo(1 << 3, "CAN2"),
    EventClass.STOP: _ClassInfo(1 << 4, "STOP"),
    EventClass.FASTIN: _ClassInfo(1 << 5, "FASTIN"),
    EventClass.TIMER: _ClassInfo(1 << 6, "TIMER"),
    EventClass.INPUT: _ClassInfo(1 << 7, "IN"),
    EventClass.COMMS: _ClassInfo(1 << 8, "COMMS"),
}
_NUMBERED = frozenset({EventClass.FASTIN, EventClass.INPUT, EventClass.COMMS})


class Events:
    """Pending events and their dispatch; the interpreter polls ``pending`` between statements."""

    def __init__(self, clock: Clock, handlers: Mapping[str, int], on_runaway: Callable[[str], None]) -> None:
        self.clock = clock
        self.handlers = handlers  # label identity -> pc
        self.on_runaway = on_runaway
        self.errors_latched: Callable[[], bool] = lambda: False
        self.on_fastin_return: Callable[[int], None] = lambda number: None
        self.disabled = 0  # EVENTDISABLE
        self.imask = 0xFFFFFF  # IMASK: every input may raise #INx
        self._pending: dict[EventClass, set[int]] = {kind: set() for kind in EventClass}
        self.pending = 0  # EVENTPENDING bits; non-zero when anything may be dispatched
        self.timer_period = 0  # TIMEREVENT, ms; 0 = off
        self.next_timer = NEVER
        self._onerror_entries = 0
        self._running_number: dict[int, int] = {}  # rank -> number of the event its handler serves

    # ----------------------------------------------------------------- raising

    def raise_event(self, kind: EventClass, number: int = 0) -> None:
        self._pending[kind].add(number)
        self.pending |= _CLASSES[kind].bit

    def has_handler(self, kind: EventClass, number: int = 0) -> bool:
        return self._handler(kind, number) is not None

    def _handler(self, kind: EventClass, number: int) -> int | None:
        label = _CLASSES[kind].label
        if kind in _NUMBERED:
            found = self.handlers.get(f"{label}{number}")
            if found is None and kind is EventClass.FASTIN:
                return self.handlers.get(label)  # #FASTIN serves every fast input
            return found
        return self.handlers.get(label)

    def error_handler(self) -> int | None:
        return self.handlers.get("ONERROR")

    # ------------------------------------------------------------ dispatching

    def take(self, running_rank: int | None) -> tuple[int, int] | None:
        for kind in EventClass:
            numbers = self._pending[kind]
            if not numbers or self.disabled & _CLASSES[kind].bit:
                continue
            if running_rank is not None and kind >= running_rank:
                return None  # a handler of this class or a higher one is running: wait for it
            for number in sorted(numbers):
                if kind is EventClass.INPUT and not self.imask >> number & 1:
                    continue
                numbers.discard(number)
                handler = self._handler(kind, number)
                if handler is not None:
                    self._refresh()
                    self._running_number[kind] = number
                    if kind is EventClass.ERROR:
                        self._onerror_entries += 1
                    return int(kind), handler
            self._refresh()
        return None

    def handler_returned(self, rank: int) -> None:
        kind = EventClass(rank)
        number = self._running_number.pop(rank, 0)
        if kind is EventClass.FASTIN:
            self.on_fastin_return(number)
        if kind is not EventClass.ERROR:
            return
        if not self.errors_latched():
            self._onerror_entries = 0
            return
        if self._onerror_entries >= ONERROR_REENTRY_LIMIT:
            self.on_runaway(
                f"#ONERROR returned {ONERROR_REENTRY_LIMIT} times in a row with an axis error still latched"
                " (clear it with CANCEL or RESET)"
            )
            return
        self.raise_event(EventClass.ERROR)

    def _refresh(self) -> None:
        self.pending = sum(_CLASSES[kind].bit for kind, numbers in self._pending.items() if numbers)

    # ------------------------------------------------------------------ timer

    def set_timer(self, period: float) -> None:
        """``TIMEREVENT``: 0 stops it; otherwise at least 10 ms, odd values rounded up (T-11 RC)."""
        value = int(period)
        if value < 0:
            raise MintError(3, detail="TIMEREVENT cannot be negative")
        if value and value < TIMER_MINIMUM_MS:
            value = TIMER_MINIMUM_MS
        value += value % 2
        self.timer_period = value
        self.next_timer = self.clock.now + value if value else NEVER

    def tick(self) -> None:
        """Raise the timer event when its period has elapsed."""
        now = self.clock.now
        if now >= self.next_timer:
            self.raise_event(EventClass.TIMER)
            self.next_timer = now + self.timer_period

    # ------------------------------------------------------------- keywords

    def register(self, table: KeywordTable) -> None:
        table.register("EVENTDISABLE", read=lambda _: float(self.disabled), write=per_channel(self._disable))
        table.register("EVENTPENDING", read=lambda _: float(self.pending), write=per_channel(self._force))
        table.register("IMASK", read=lambda _: float(self.imask), write=per_channel(self._mask))
        table.register("IPEND", read=lambda _: float(self._bits(EventClass.INPUT)), write=per_channel(self._ipend))
        table.register("TIMEREVENT", read=lambda _: float(self.timer_period), write=per_channel(self._timer))

    def _disable(self, _: int | None, value: float) -> None:
        self.disabled = int(value) & 0x1FF

    def _force(self, _: int | None, value: float) -> None:
        bits = int(value)
        for kind, info in _CLASSES.items():
            if bits & info.bit:
                if not self._pending[kind]:
                    self._pending[kind].add(0)
            else:
                self._pending[kind].clear()
        self._refresh()

    def _mask(self, _: int | None, value: float) -> None:
        self.imask = int(value) & 0xFFFFFF

    def _bits(self, kind: EventClass) -> int:
        return sum(1 << number for number in self._pending[kind])

    def _ipend(self, _: int | None, value: float) -> None:
        bits = int(value)
        self._pending[EventClass.INPUT] = {number for number in range(24) if bits >> number & 1}
        self._refresh()

    def _timer(self, _: int | None, value: float) -> None:
        self.set_timer(value)
