"""Mint events: which handler runs when, as the controller dispatches them (spec §7).

Each event class has a rank (its priority, 0 highest) and a bit in the
controller's disable and pending masks. A pending event runs at the next
statement boundary if its class is enabled and its handler exists. On NextMove
it pre-empts a lower-ranked handler that is running (a handler of the same
class waits until the running one returns); on MintDrive and ServoNode 51
handlers do not pre-empt one another, except ``#ONERROR``, and the order and
the mask layout (``HANDLERDISABLE``/``HANDLERPENDING``) differ (EV-2, EV-3, EV-5).
A disabled class keeps its pending flag. Handlers serve their own file: the
configuration file's while it runs, then the program's.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import replace
from enum import IntEnum

from mintlang.records import record
from mintlang.runtime.clock import NEVER, Clock
from mintlang.runtime.io_banks import BankSelection
from mintlang.runtime.keywords import KeywordTable, per_channel
from mintlang.runtime.ranges import ranged, table_default
from mintlang.semantic.events import event_of

ONERROR_REENTRY_LIMIT = 100  # consecutive re-entries of #ONERROR with an error still latched (AX-7 RC)


class EventClass(IntEnum):
    """The event classes, in NextMove priority order (EV-2)."""

    ERROR = 0
    CAN1 = 1
    CAN2 = 2
    STOP = 3
    FASTIN = 4
    TIMER = 5
    INPUT = 6
    COMMS = 7
    MOVEBUFFERLOW = 8  # MintMT only (mintlang/MINTMT.md, MT-14)


_LABELS: Mapping[EventClass, str] = {  # the handler label, followed by the event's number where it has one
    EventClass.ERROR: "ONERROR",
    EventClass.CAN1: "CAN1",
    EventClass.CAN2: "CAN2",
    EventClass.STOP: "STOP",
    EventClass.FASTIN: "FASTIN",
    EventClass.TIMER: "TIMER",
    EventClass.INPUT: "IN",
    EventClass.COMMS: "COMMS",
    EventClass.MOVEBUFFERLOW: "MOVEBUFFERLOW",
}
_NUMBERED = frozenset({EventClass.FASTIN, EventClass.INPUT, EventClass.COMMS})
_E = EventClass


@record
class Dispatch:
    """How a controller dispatches events: priority order, pre-emption and its mask keywords."""

    order: tuple[EventClass, ...]  # highest priority first; the index is the rank the interpreter sees
    preemptive: bool
    disable_keyword: str
    pending_keyword: str
    bits: Mapping[EventClass, int]  # the class's bit in those masks
    timer_minimum_ms: int  # the shortest TIMEREVENT period (T-11)
    highest_input_first: bool = False  # Mint v3: #IN7 before #IN0 (001:2574-2583)
    inputs_interrupt_inputs: bool = False  # Mint v3: another input's handler pre-empts a running #INx (001:2548-2549)
    onerror_repeats: bool = True  # #ONERROR runs again while an axis error stays latched (AX-7); v3: once per error
    # an input without a handler is pending in IPEND and, enabled, holds back the events below it (000:5057-5059,
    # 12625-12630); the v3 guide says neither, and its triggered moves use inputs without handlers (001:4211-4225)
    unhandled_inputs_pend: bool = True


NEXTMOVE = Dispatch(
    order=(_E.ERROR, _E.CAN1, _E.CAN2, _E.STOP, _E.FASTIN, _E.TIMER, _E.INPUT, _E.COMMS),
    preemptive=True,
    disable_keyword="EVENTDISABLE",
    pending_keyword="EVENTPENDING",
    bits={_E.ERROR: 2, _E.CAN1: 4, _E.CAN2: 8, _E.STOP: 16, _E.FASTIN: 32, _E.TIMER: 64, _E.INPUT: 128, _E.COMMS: 256},
    timer_minimum_ms=10,
)
NEXTMOVE_MINTMT = replace(
    NEXTMOVE,
    order=(*NEXTMOVE.order, _E.MOVEBUFFERLOW),
    bits={**NEXTMOVE.bits, _E.MOVEBUFFERLOW: 1 << 16},  # beyond the masks' bits: EVENTPENDING never shows it (MT-14)
)
"""A NextMove running MintMT: its MOVEBUFFERLOW event ranks below every other (the notes give no rank)."""
MINTDRIVE = Dispatch(
    order=(_E.ERROR, _E.FASTIN, _E.STOP, _E.CAN1, _E.CAN2, _E.TIMER, _E.INPUT, _E.COMMS),
    preemptive=False,
    disable_keyword="HANDLERDISABLE",
    pending_keyword="HANDLERPENDING",
    bits={_E.ERROR: 1, _E.FASTIN: 2, _E.STOP: 4, _E.CAN1: 8, _E.CAN2: 16, _E.TIMER: 32, _E.INPUT: 64, _E.COMMS: 256},
    timer_minimum_ms=40,
)


class Events:
    """Pending events and their dispatch; the interpreter polls ``pending`` between statements."""

    def __init__(
        self,
        clock: Clock,
        handlers: Mapping[str, int],
        on_runaway: Callable[[str], None],
        dispatch: Dispatch,
        banks: BankSelection,
    ) -> None:
        self.clock = clock
        self.banks = banks  # IMASK and IPEND address the inputs of the bank BANK selects
        self.dispatch = dispatch
        self.handlers = handlers  # the program's handlers: label identity -> pc
        self.configuration_handlers: Mapping[str, int] = {}
        self.in_configuration: Callable[[], bool] = lambda: False  # whether the configuration file is running
        self.on_runaway = on_runaway
        self.axis_in_error: Callable[[], int | None] = lambda: None  # the lowest-numbered axis with an error latched
        self.on_onerror_again: Callable[[int], None] = lambda axis: None  # ERR and ERRAXIS for a call made again
        self.on_fastin_return: Callable[[int], None] = lambda number: None
        self.disabled: frozenset[EventClass] = frozenset()  # EVENTDISABLE / HANDLERDISABLE
        self.disabled_unmodelled = 0  # bits written to that mask for handlers not simulated (NextMove's serial event)
        self.inputs_set_unhandled = 0  # IPEND bits written for inputs without an #INx: set until written clear
        self.imask = 0  # IMASK, one bit per input of the controller: those that may raise #INx
        self._pending: dict[EventClass, set[int]] = {kind: set() for kind in EventClass}
        self.pending = 0  # the pending mask (EVENTPENDING or HANDLERPENDING); non-zero when anything may be dispatched
        self.timer_period = 0  # TIMEREVENT, ms; 0 = off
        self.next_timer = NEVER
        self._onerror_entries = 0
        self._running_numbers: dict[int, list[int]] = {}  # rank -> numbers of the events its handlers serve

    # ----------------------------------------------------------------- raising

    def raise_event(self, kind: EventClass, number: int = 0) -> None:
        self._pending[kind].add(number)
        self.pending |= self.dispatch.bits[kind]

    def raise_input(self, number: int) -> None:
        """Input ``number``'s event: pending for its ``#INx``; without one, its IPEND bit is set until written
        clear (000:12621-12623) and, while IMASK enables it, holds back every lower event (000:5057-5059)."""
        if self.has_handler(EventClass.INPUT, number):
            self.raise_event(EventClass.INPUT, number)
        elif self.dispatch.unhandled_inputs_pend:
            self.inputs_set_unhandled |= 1 << number

    def is_pending(self, kind: EventClass) -> bool:
        return bool(self._pending[kind])

    def has_handler(self, kind: EventClass, number: int = 0) -> bool:
        return self._handler(kind, number) is not None

    def _running_handlers(self) -> Mapping[str, int]:
        """The handlers of the file running: neither file can call the other's subroutines."""
        return self.configuration_handlers if self.in_configuration() else self.handlers

    def _handler(self, kind: EventClass, number: int) -> int | None:
        label = _LABELS[kind]
        handlers = self._running_handlers()
        if kind in _NUMBERED:
            found = handlers.get(f"{label}{number}")
            if found is None and kind is EventClass.FASTIN:
                return handlers.get(label)  # #FASTIN serves every fast input
            return found
        return handlers.get(label)

    def error_handler(self) -> int | None:
        """``#ONERROR`` for a synchronous error; None also while it is disabled, so the error ends the run."""
        if EventClass.ERROR in self.disabled:
            return None
        return self._handler(EventClass.ERROR, 0)

    def _lowest_handled(self, kind: EventClass) -> int:
        """The number of the class's lowest-numbered handler (0 when there is none): what a forced event runs."""
        label = _LABELS[kind]
        events = (event_of(name) for name in self._running_handlers())  # #IN01 is a plain label, no handler's
        return min((e.number for e in events if e is not None and e.kind == label and e.number is not None), default=0)

    # ------------------------------------------------------------ dispatching

    def take(self, running_rank: int | None) -> tuple[int, int] | None:
        """The (rank, handler pc) to call now, given the rank of the handler running (None: the program)."""
        dispatch = self.dispatch
        holding = self._input_holding_back()
        for rank, kind in enumerate(dispatch.order):
            numbers = self._pending[kind]
            if kind in self.disabled or not (numbers or (kind is EventClass.INPUT and holding is not None)):
                continue
            nested = rank == running_rank and kind is EventClass.INPUT and dispatch.inputs_interrupt_inputs
            if running_rank is not None and not nested and (rank >= running_rank or (not dispatch.preemptive and rank)):
                return None  # wait for the running handler (only #ONERROR interrupts without pre-emption)
            running = self._running_numbers.get(rank, []) if nested else []
            for number in sorted(numbers, key=self._input_priority if kind is EventClass.INPUT else None):
                if kind is EventClass.INPUT and holding is not None and self._input_priority(number) > holding:
                    break  # below the enabled input without a handler
                if (kind is EventClass.INPUT and not self.imask >> number & 1) or number in running:
                    continue  # masked, or its own handler runs: it waits for the RETURN
                numbers.discard(number)
                handler = self._handler(kind, number)
                if handler is not None:
                    self._refresh()
                    self._running_numbers.setdefault(rank, []).append(number)
                    if kind is EventClass.ERROR:
                        self._onerror_entries += 1
                    return rank, handler
            self._refresh()
            if nested or (kind is EventClass.INPUT and holding is not None):
                return None
        return None

    def _input_priority(self, number: int) -> int:
        """Where input ``number``'s event ranks among the inputs', 0 highest: ``#IN0`` first (v3: the highest)."""
        return -number if self.dispatch.highest_input_first else number

    def _input_holding_back(self) -> int | None:
        """The priority of the highest input IMASK enables that is pending without a handler, which holds back
        the events below it (000:5057-5059); None when there is none, or while input events are disabled."""
        enabled = self.inputs_set_unhandled & self.imask
        if not enabled or EventClass.INPUT in self.disabled or not self.dispatch.unhandled_inputs_pend:
            return None
        return min(self._input_priority(number) for number in range(enabled.bit_length()) if enabled >> number & 1)

    def handler_returned(self, rank: int) -> None:
        kind = self.dispatch.order[rank]
        running = self._running_numbers.get(rank)
        number = running.pop() if running else 0
        if kind is EventClass.FASTIN:
            self.on_fastin_return(number)
        if kind is not EventClass.ERROR:
            return
        axis = self.axis_in_error() if self.dispatch.onerror_repeats else None
        if axis is None:
            self._onerror_entries = 0
            return
        if self._onerror_entries >= ONERROR_REENTRY_LIMIT:
            self.on_runaway(
                f"#ONERROR returned {ONERROR_REENTRY_LIMIT} times in a row with an axis error still latched"
                " (clear it with CANCEL or RESET)"
            )
            return
        self.on_onerror_again(axis)
        self.raise_event(EventClass.ERROR)

    def _refresh(self) -> None:
        self.pending = sum(self.dispatch.bits[kind] for kind, numbers in self._pending.items() if numbers)

    # ------------------------------------------------------------------ timer

    def set_timer(self, period: float) -> None:
        """``TIMEREVENT``: 0 stops it; otherwise at least the controller's minimum, odd values rounded up (T-11 RC)."""
        value = int(period)
        minimum = self.dispatch.timer_minimum_ms
        if value and value < minimum:
            value = minimum
        value += value % 2
        self.timer_period = value
        self.next_timer = self.clock.now + value if value else NEVER

    def tick(self) -> None:
        """Raise the timer event when its period has elapsed; the next one falls a whole period after it was due,
        whether or not the ticks between were processed."""
        now = self.clock.now
        if now >= self.next_timer:
            self.raise_event(EventClass.TIMER)
            period = self.timer_period
            self.next_timer = now + period - (now - self.next_timer) % period

    def next_timer_event(self) -> int:
        """The tick at which the timer next calls #TIMER; NEVER without one to call, so a timer left running
        (on MintDrive from power-up) wakes nothing and a program that waits on nothing else is deadlocked. NEVER
        too while its event is pending already (behind an INPUT, say): running out again changes nothing,
        and ``tick`` catches the period up whenever the next tick is processed."""
        timer = EventClass.TIMER
        return self.next_timer if self.has_handler(timer) and not self._pending[timer] else NEVER

    # ------------------------------------------------------------- keywords

    def register(self, table: KeywordTable) -> None:
        controller = table.controller
        for dispatch in (NEXTMOVE, MINTDRIVE):
            disable = ranged(dispatch.disable_keyword, controller, self._disable(dispatch))
            table.register(dispatch.disable_keyword, read=self._disabled_mask(dispatch), write=per_channel(disable))
            force = ranged(dispatch.pending_keyword, controller, self._force(dispatch))
            table.register(dispatch.pending_keyword, read=self._pending_mask(dispatch), write=per_channel(force))
        table.register("EVENTACTIVE", read=self._active_mask)
        mask = ranged("IMASK", controller, self._mask)
        table.register("IMASK", read=lambda _: float(self.banks.inputs(self.imask)), write=per_channel(mask))
        ipend = ranged("IPEND", controller, self._ipend)
        table.register(
            "IPEND",
            read=lambda _: float(self.banks.inputs(self._pending_inputs() | self.inputs_set_unhandled)),
            write=per_channel(ipend),
        )
        timer = ranged("TIMEREVENT", controller, self._timer)
        table.register("TIMEREVENT", read=lambda _: float(self.timer_period), write=per_channel(timer))
        self.set_timer(table_default("TIMEREVENT", controller) or 0.0)  # at power-up: 10000 ms on MintDrive

    def _disabled_mask(self, dispatch: Dispatch) -> Callable[[int | None], float]:
        """The mask as written: a bit for a handler the run does not simulate reads back too (000:10137, 10140)."""
        bits = tuple(dispatch.bits.items())  # a dict view in a closure is no state a snapshot can save
        return lambda _: float(sum((bit for kind, bit in bits if kind in self.disabled), self.disabled_unmodelled))

    def _pending_mask(self, dispatch: Dispatch) -> Callable[[int | None], float]:
        return lambda _: float(sum(bit for kind, bit in dispatch.bits.items() if self._pending[kind]))

    def _active_mask(self, _: int | None) -> float:
        """EVENTACTIVE: the handlers begun and not yet returned, those a higher one pre-empted included, in the
        bits of EVENTDISABLE and EVENTPENDING (000:4385-4392). NextMove's keyword (000:18061): MintDrive's layout
        is never used for it."""
        order, bits = self.dispatch.order, NEXTMOVE.bits
        return float(sum(bits.get(order[rank], 0) for rank, running in self._running_numbers.items() if running))

    def _disable(self, dispatch: Dispatch) -> Callable[[int | None, float], None]:
        def write(_: int | None, value: float) -> None:
            bits = int(value)
            self.disabled = frozenset(kind for kind, bit in dispatch.bits.items() if bits & bit)
            self.disabled_unmodelled = bits & ~sum(dispatch.bits.values())

        return write

    def _force(self, dispatch: Dispatch) -> Callable[[int | None, float], None]:
        """Writing the pending mask forces (bit set) or clears (bit clear) each class's pending event."""

        def write(_: int | None, value: float) -> None:
            bits = int(value)
            for kind, bit in dispatch.bits.items():
                if bits & bit:
                    if not self._pending[kind]:
                        self._pending[kind].add(self._lowest_handled(kind) if kind in _NUMBERED else 0)
                else:
                    self._pending[kind].clear()
            self._refresh()

        return write

    def _mask(self, _: int | None, value: float) -> None:
        self.imask = self.banks.with_inputs(self.imask, int(value))

    def _pending_inputs(self) -> int:
        return sum(1 << number for number in self._pending[EventClass.INPUT])

    def _ipend(self, _: int | None, value: float) -> None:
        """Writing IPEND sets or clears each input's pending bit. A bit set for an input with no #INx handler
        calls nothing and stays set until written clear (000:12621-12623); the others are events to dispatch."""
        pending = self.banks.with_inputs(self._pending_inputs() | self.inputs_set_unhandled, int(value))
        numbers = {number for number in range(pending.bit_length()) if pending >> number & 1}
        handled = {number for number in numbers if self.has_handler(EventClass.INPUT, number)}
        self._pending[EventClass.INPUT] = handled
        self.inputs_set_unhandled = sum(1 << number for number in numbers - handled)
        self._refresh()

    def _timer(self, _: int | None, value: float) -> None:
        self.set_timer(value)
