"""Output moves: digital outputs set from the move buffer when their place in it is reached (004:288-304, MT-22).

``MOVEOUT(axis, bank) = pattern``, ``MOVEOUTX(axis, channel) = state`` and
``MOVEPULSEOUTX(axis, channel) = ms`` each take a place in the axis's buffer,
behind the moves loaded before them, and are triggered like them (``GO``,
``TRIGGERMODE``). When the move before one ends, it acts and the move behind it
starts in the same tick: MOVEOUT sets the whole bank to the pattern (the other
outputs of the bank off), MOVEOUTX one channel, and MOVEPULSEOUTX turns a
channel on and, that many milliseconds later, off again. The simulated
controller has the one bank of v4's ``OUT``: bank 0. Like OUT, they leave an
output a drive enable is assigned to (``DigitalIO.set_outputs``).
"""

from __future__ import annotations

from collections.abc import Callable

from mintlang.runtime.clock import NEVER
from mintlang.runtime.errors import MISSING_PARAMETER, OUT_OF_RANGE, TOO_MANY_VALUES, MintError
from mintlang.runtime.io import INVALID_OUTPUT, DigitalIO
from mintlang.runtime.io_banks import with_bit
from mintlang.runtime.keywords import Channels, IndexedWriter, KeywordTable, Values
from mintlang.runtime.motion.axis import Request
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.ranges import UNBOUNDED, check_range, table_bounds


class OutputMoves:
    """The three keywords, and the pulses still to end (a ``Monitor``)."""

    def __init__(self, motion: Motion, io: DigitalIO, loaded: Callable[[Channels | None], None]) -> None:
        self.motion = motion
        self.io = io
        self.loaded = loaded  # TRIGGERMODE: starts what was just loaded where triggering is automatic
        self.pulse_ends: dict[int, int] = {}  # channel -> the tick its pulse ends
        self.pulse_limits = UNBOUNDED  # MOVEPULSEOUTX's milliseconds: the controller's row, once registered

    def register(self, table: KeywordTable) -> None:
        table.register("MOVEOUT", indexed_write=self._loader(self._bank))
        table.register("MOVEOUTX", indexed_write=self._loader(self._channel))
        self.pulse_limits = table_bounds("MOVEPULSEOUTX", table.controller, table.dialect)  # MT-22: whole ms, 1 on
        table.register("MOVEPULSEOUTX", indexed_write=self._loader(self._pulse))

    # ------------------------------------------------------------ loading

    def _loader(self, action: Callable[[int, float], Callable[[], None]]) -> IndexedWriter:
        """The writer loading an output move made by ``action(index, value)``, which checks both first."""

        def write(channels: Channels | None, indices: tuple[int, ...], values: Values) -> bool:
            if channels is not None and len(channels) > 1:
                raise MintError(TOO_MANY_VALUES, detail="an output move is loaded on one axis")
            if len(indices) != 1 or len(values) != 1 or values[0] is None:
                raise MintError(MISSING_PARAMETER, detail="an output move takes an axis, a bank or channel and a value")
            axis = self.motion.axis(channels[0] if channels else None)
            act = action(indices[0], values[0])
            axis.require_ready()
            if axis.buffer_free() <= 0:
                if axis.move is not None:
                    self.motion.clock.changes_at(axis.move.end)
                return True
            axis.buffer.append(Request(0, (axis.number,), _acting(act), ident=axis.load_ident, instant=True))
            self.loaded((axis.number,))
            return False

        return write

    def _bank(self, bank: int, pattern: float) -> Callable[[], None]:
        banks = self.io.banks.banks
        if not 0 <= bank < banks.count:
            raise MintError(OUT_OF_RANGE, detail=f"MOVEOUT's bank is 0 to {banks.count - 1}, one per card")
        if pattern != int(pattern) or not 0 <= pattern < banks.output_words:
            raise MintError(OUT_OF_RANGE, detail=f"MOVEOUT takes a pattern of 0 to {banks.output_words - 1}")
        return lambda: self._set_bank(bank, int(pattern))

    def _channel(self, channel: int, state: float) -> Callable[[], None]:
        self._check(channel)
        return lambda: self._set(channel, on=bool(state))

    def _pulse(self, channel: int, milliseconds: float) -> Callable[[], None]:
        self._check(channel)
        check_range("MOVEPULSEOUTX", milliseconds, self.pulse_limits)

        def pulse() -> None:
            self._set(channel, on=True)
            self.pulse_ends[channel] = self.motion.clock.now + int(milliseconds)

        return pulse

    def _check(self, channel: int) -> None:
        if channel not in self.io.outputs:
            raise MintError(INVALID_OUTPUT, channel, f"channels are {self.io.outputs}")

    # ------------------------------------------------------------ acting

    def _set_bank(self, bank: int, pattern: int) -> None:
        self.io.set_outputs(self.io.banks.banks.with_output_word(self.io.out, bank, pattern))

    def _set(self, channel: int, *, on: bool) -> None:
        self.io.set_outputs(with_bit(self.io.out, channel, on))

    # ------------------------------------------------------------ Monitor

    def before_motion(self, tick: int) -> None:
        return None

    def after_motion(self, tick: int) -> None:
        for channel, end in list(self.pulse_ends.items()):
            if tick >= end:
                del self.pulse_ends[channel]
                self._set(channel, on=False)

    def next_required(self, now: int) -> int:
        return min(self.pulse_ends.values(), default=NEVER)


def _acting(act: Callable[[], None]) -> Callable[[int], None]:
    """A request's build: the output move acts when it starts, and moves nothing."""

    def build(tick: int) -> None:
        act()

    return build
