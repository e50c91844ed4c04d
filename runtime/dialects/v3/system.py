"""Mint v3 controller-wide keywords: I/O bits, analog inputs, TIME, the error state, interrupts, the terminal.

* ``IN`` reads the levels of the 8 inputs, ``IN0``..``IN7`` one each (001:4284-4330); an
  input's interrupt comes on its falling edge, see ``events.py``.
* ``OUT0``..``OUT7`` write one output and cannot be read (001:943-946, 10602-10647); ``IN.x`` and
  ``OUT.x`` outside 0..7 are "Out of Range" (001:8965, 10592).
* ``ANALOGUE1``..``3`` read 0..1023 (001:5736-5770) from the scenario's percent of the
  ±10 V range: 0 V reads 512, the zero of the guide's joystick (V3-7).
* ``TIME`` counts in steps of the 2 ms loop time and wraps after 65536 loops (001:12062-12071).
* ``ERR`` and ``ERRAXIS`` hold the last error #ONERROR saw (001:4918-4968); before any, the
  guide gives no value.
* ``DINT``/``EINT`` disable and enable #IN0..#IN7 and #FASTPOS (001:7365-7396, 7531-7545);
  ``PON``/``POFF`` switch the ``?`` of INPUT on and off (001:10791-10847).
* ``LASTERR`` displays the message that last ended a program: v4's, none in a run from power-up.
* ``LIMIT``, ``STOPSW`` and ``ERRORIN`` read the dedicated inputs (``controllers.py``);
  ``ERRORIN`` makes the error input active low (0) or high (1), or disables it (2, the
  default) (001:7841-7876).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from mintlang.runtime.clock import Clock
from mintlang.runtime.dialects.v3.controllers import ERROR_INPUT, USER_INPUTS
from mintlang.runtime.dialects.v3.handlers import V4Handlers
from mintlang.runtime.errors import OUT_OF_RANGE, MintError, NotSimulated
from mintlang.runtime.events import EventClass, Events
from mintlang.runtime.interpreter.vm import Interpreter
from mintlang.runtime.io import DigitalIO
from mintlang.runtime.keywords import Channels, KeywordTable, Values, Writer, per_channel
from mintlang.runtime.motion.axis import Axis
from mintlang.runtime.system import System
from mintlang.runtime.terminal import Terminal

LOOP_MS = 2  # LOOPTIME 2, the default (001:9906-9912)
TIME_WRAP_MS = 65536 * LOOP_MS
ANALOG_COUNTS = 1024  # 10 bits (001:5760)
INPUT_QUERY = "?"  # the INPUT prompt (001:2769-2775, 10833-10845)
INTERRUPTS = frozenset({EventClass.INPUT, EventClass.FASTIN})  # what DINT disables (001:7375)
BYTE = 255
USER_OUTPUTS = 8  # OUT0..OUT7 (001:10602)


class V3System:
    """The controller-wide v3 keywords, on the v4 parts they act on."""

    def __init__(
        self,
        v4: V4Handlers,
        *,
        clock: Clock,
        axes: Sequence[Axis],
        io: DigitalIO,
        events: Events,
        system: System,
        vm: Interpreter,
    ) -> None:
        self.v4 = v4
        self.clock = clock
        self.axes = axes
        self.io = io
        self.events = events
        self.system = system
        self.vm = vm

    def register(self, table: KeywordTable, terminal: Terminal) -> None:
        for name in ("IMASK", "IPEND", "INKEY", "CLS", "BEEP", "BOL", "LOCATE", "LIMIT"):
            table.alias(name, self.v4.access(name))
        read_out, write_out = self.v4.read("OUT"), self.v4.write("OUT")
        table.register("OUT", read=lambda channel: read_out(_output(channel)), write=_within_the_outputs(write_out))
        table.alias("STOPSW", self.v4.access("STOPSWITCH"))
        table.register("LASTERR", command=self.v4.access("LASTERR").command)  # a command in v3 (001:9632-9642)
        table.register("IN", read=self._input)
        for number in range(USER_INPUTS):
            table.register(f"IN{number}", read=lambda _, bit=number: self._input(bit))
            table.register(f"OUT{number}", write=per_channel(self._output(number)))
        for number in range(1, 4):
            table.register(f"ANALOGUE{number}", read=lambda _, channel=number - 1: self._analogue(channel))
        table.register("TIME", read=self._time, write=per_channel(self._write_time))
        table.register("ERR", read=self._last_error("ERR", lambda: self.vm.err))
        table.register("ERRAXIS", read=self._last_error("ERRAXIS", lambda: self.vm.erraxis))
        table.register("ERRORIN", read=self.v4.read("ERRORSWITCH"), write=per_channel(self._write_error_input))
        table.register("LOOPTIME", read=lambda _: float(LOOP_MS), write=per_channel(self._looptime))
        table.register("DINT", command=self._interrupts(enabled=False))
        table.register("EINT", command=self._interrupts(enabled=True))
        table.register("PON", command=self._prompt(terminal, INPUT_QUERY))
        table.register("POFF", command=self._prompt(terminal, ""))
        table.register("AUTO", command=lambda channels, arguments: False)  # the run starts as at power-up
        terminal.query = INPUT_QUERY
        self.events.imask = BYTE

    def reset(self) -> None:
        """What RESET clears besides the axes: outputs, TIME, FASTPOS, IMASK (001:11427-11444)."""
        self.io.out = 0
        self.system.time_origin = self.clock.now
        self.system.fast_positions = [0.0] * len(self.system.fast_positions)
        self.events.imask = BYTE

    # ---------------------------------------------------------------- I/O

    def _input(self, channel: int | None) -> float:
        """The levels of the 8 user inputs: v3 latches no edges for IN (001:4290-4310)."""
        read = self.v4.read("IN")
        if channel is None:
            return float(int(read(None)) & BYTE)
        if not 0 <= channel < USER_INPUTS:  # "Out of Range" outside 0 to 7 (001:8965)
            raise MintError(OUT_OF_RANGE, detail=f"IN.{channel}: the inputs are 0 to {USER_INPUTS - 1}")
        return read(channel)

    def _output(self, number: int) -> Callable[[int | None, float], None]:
        write_bit = self.v4.write_one("OUT")
        return lambda _, value: write_bit(number, value)

    def _analogue(self, channel: int) -> float:
        percent = self.v4.read("ADC")(channel)
        return float(min(int((percent + 100) * ANALOG_COUNTS / 200), ANALOG_COUNTS - 1))

    # ---------------------------------------------------------------- time and errors

    def _time(self, _: int | None) -> float:
        self.clock.changes_next_tick()
        elapsed = (self.clock.now - self.system.time_origin) % TIME_WRAP_MS
        return float(elapsed - elapsed % LOOP_MS)

    def _write_time(self, _: int | None, value: float) -> None:
        """``TIME = 0`` restarts it (001:12060); the table's range starts at 2, its own example at 0 (V3-5)."""
        self.system.time_origin = self.clock.now - int(value)

    def _last_error(self, name: str, value: Callable[[], float]) -> Callable[[int | None], float]:
        def read(_: int | None) -> float:
            if value() < 0:
                raise NotSimulated(name, "read before any error, or after one on no axis: the guide gives no value")
            return value()

        return read

    def _write_error_input(self, _: int | None, value: float) -> None:
        """0 active low, 1 active high, 2 disabled (001:7863-7866), as the table holds it (``v3_ranges``)."""
        for axis in self.axes:
            axis.set("ERRORINPUT", -1.0 if value == 2 else float(ERROR_INPUT))
        bit = 1 << ERROR_INPUT
        self.io.active_level = self.io.active_level | bit if value == 1 else self.io.active_level & ~bit

    def _looptime(self, _: int | None, value: float) -> None:
        if value != LOOP_MS:
            raise NotSimulated("LOOPTIME", "the 1 ms loop of one axis")

    # ---------------------------------------------------------------- interrupts and prompt

    def _interrupts(self, *, enabled: bool) -> Callable[[Channels | None, tuple[float, ...]], bool]:
        def command(channels: Channels | None, arguments: tuple[float, ...]) -> bool:
            events = self.events
            events.disabled = events.disabled - INTERRUPTS if enabled else events.disabled | INTERRUPTS
            return False

        return command

    @staticmethod
    def _prompt(terminal: Terminal, query: str) -> Callable[[Channels | None, tuple[float, ...]], bool]:
        def command(channels: Channels | None, arguments: tuple[float, ...]) -> bool:
            terminal.query = query
            return False

        return command


def _output(channel: int | None) -> int | None:
    """``OUT.a`` with ``a`` outside 0 to 7 is "Out of Range" (001:10592), an error of no axis."""
    if channel is not None and not 0 <= channel < USER_OUTPUTS:
        raise MintError(OUT_OF_RANGE, detail=f"OUT.{channel}: the outputs are 0 to {USER_OUTPUTS - 1}")
    return channel


def _within_the_outputs(write: Writer) -> Writer:
    def checked(channels: Channels | None, values: Values) -> bool:
        for channel in channels or ():
            _output(channel)
        return write(channels, values)

    return checked
