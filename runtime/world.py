"""The scripted world around the controller: input levels, keys, analog values, host traffic.

Timed records apply at the start of their tick; inputs tied to an encoder
follow the axis's physical count (not ``POS``, which homing and writes move).
``next_change`` tells the simulator the next tick at which anything here can
change, so it can skip the ticks in between.
"""

from __future__ import annotations

import operator
from collections.abc import Callable, Sequence

from mintlang.runtime.clock import NEVER
from mintlang.runtime.io import DigitalIO
from mintlang.runtime.io_banks import with_bit
from mintlang.runtime.motion.axis import Axis
from mintlang.runtime.scenario.stimulus import Scenario
from mintlang.runtime.terminal import Terminal

_COMPARE = {"<=": operator.le, ">=": operator.ge, "<": operator.lt, ">": operator.gt}


class World:
    def __init__(
        self,
        scenario: Scenario,
        *,
        io: DigitalIO,
        axes: Sequence[Axis],
        terminal: Terminal,
        host: Callable[[bytes], bytes],
        fast_digital_inputs: frozenset[int] = frozenset(),
    ) -> None:
        self.io = io
        self.fast_digital_inputs = fast_digital_inputs  # digital inputs whose rising edge fires their fast input
        self.axes = axes
        self.terminal = terminal
        self.host = host
        self.fast_inputs_due: list[int] = []  # fast inputs fired this tick; latched after the servo loop (T-6 RC)
        self.position_inputs = scenario.position_inputs
        self.watched_axes = tuple(sorted({record.axis for record in scenario.position_inputs}))
        timed: list[tuple[int, int, Callable[[], None]]] = []
        for order, record in enumerate(scenario.inputs):
            timed.append((record.time_ms, order, self._level(record.channel, record.level)))
        for order, record in enumerate(scenario.adc):
            timed.append((record.time_ms, order, self._adc(record.channel, record.percent)))
        for order, record in enumerate(scenario.keys):
            timed.append((record.time_ms, order, self._keys(record.text)))
        for order, record in enumerate(scenario.fast_inputs):
            timed.append((record.time_ms, order, self._fast(record.channel)))
        for order, record in enumerate(scenario.host_packets):
            timed.append((record.time_ms, order, self._packet(record.data)))
        timed.sort(key=lambda entry: (entry[0], entry[1]))
        self._timed = timed
        self._next = 0
        self.levels = 0
        self.host_replies: list[tuple[int, bytes]] = []
        self._now = 0

    def apply(self, tick: int) -> int:
        """Apply everything due by ``tick``; return the electrical input levels for this tick."""
        self._now = tick
        timed = self._timed
        while self._next < len(timed) and timed[self._next][0] <= tick:
            timed[self._next][2]()
            self._next += 1
        levels = self.levels
        for record in self.position_inputs:
            bit = 1 << record.channel
            if _COMPARE[record.operator](self.axes[record.axis].measured, record.counts):
                levels |= bit
            else:
                levels &= ~bit
        return levels

    def next_change(self, now: int) -> int:
        upcoming = self._timed[self._next][0] if self._next < len(self._timed) else NEVER
        for number in self.watched_axes:
            axis = self.axes[number]
            if axis.move is not None or axis.measured != axis.previous_measured or axis.plant.closed_loop:
                return now + 1
        return max(upcoming, now + 1)

    def _level(self, channel: int, level: int) -> Callable[[], None]:
        fires = channel in self.fast_digital_inputs

        def apply() -> None:
            if fires and level and not self.levels >> channel & 1:
                self.fast_inputs_due.append(channel)
            self.levels = with_bit(self.levels, channel, bool(level))

        return apply

    def _adc(self, channel: int, percent: float) -> Callable[[], None]:
        def apply() -> None:
            if 0 <= channel < len(self.io.adc):
                self.io.adc[channel] = percent

        return apply

    def _keys(self, text: str) -> Callable[[], None]:
        return lambda: self.terminal.type_keys(text)

    def _fast(self, channel: int) -> Callable[[], None]:
        return lambda: self.fast_inputs_due.append(channel)

    def _packet(self, data: bytes) -> Callable[[], None]:
        def apply() -> None:
            reply = self.host(data)
            if reply:
                self.host_replies.append((self._now, reply))

        return apply
