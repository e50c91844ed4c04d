"""Controller-wide keywords: time, error state, terminal, node, comms array, fast latches, auxiliary encoders.

Nothing turns an auxiliary encoder in the simulation: it reads what the program
last wrote to AUXENCODER (0 at power-up), and a fast input latches that.
"""

from __future__ import annotations

from collections.abc import Sequence

from mintlang.comms_map import system_element
from mintlang.controllers import ChannelRange, profile
from mintlang.runtime.clock import Clock
from mintlang.runtime.comms.array import CommsArray
from mintlang.runtime.errors import INVALID_CHANNEL, MintError
from mintlang.runtime.interpreter.line_trace import LineTrace
from mintlang.runtime.interpreter.vm import Interpreter
from mintlang.runtime.keywords import Channels, KeywordTable, per_channel
from mintlang.runtime.motion.axis import Axis
from mintlang.runtime.motion.commands import channel_range, check_channel
from mintlang.runtime.ranges import check_range, ranged, table_bounds
from mintlang.runtime.terminal import Terminal

TIME_LIMIT = 16_777_216  # TIME wraps after 16777215 (T-7 RC), where its table gives no range
DEFAULT_NODE = 2
BUILD_NUMBER = 0.0  # COMMS(239): the simulator has no firmware build
# LASTERR: a run starts at power-up and ends when its program is terminated, so no program has been terminated
# by an error before it; -1 is the error list's "Success", what ERR reads before any error (000:18508-18510).
NO_ERROR = -1.0


class System:
    def __init__(
        self,
        clock: Clock,
        vm: Interpreter,
        terminal: Terminal,
        axes: Sequence[Axis],
        table: KeywordTable,
        *,
        auxiliary_encoders: int = 0,
    ) -> None:
        self.clock = clock
        self.vm = vm
        self.terminal = terminal
        self.axes = axes
        self.table = table
        self.time_origin = 0
        self.node = DEFAULT_NODE
        self.comms = CommsArray(self._system_read, self._system_write)
        self._unnamed = {  # the misc comms elements no keyword reads (CM-1)
            "EXECUTION_STATUS": self._execution_status,
            "BUFFER": self._buffer,
            "LINE": self._line,
            "FIRMWAREREVISION": lambda: BUILD_NUMBER,
        }
        self.fast_positions: list[float] = [0.0] * len(axes)  # FASTPOS per axis: the position latched, in counts
        self.fast_encoders: list[float] = [0.0] * len(axes)
        self.auxiliary_encoders: list[float] = [0.0] * auxiliary_encoders  # AUXENCODER, counts
        self.fast_auxiliary: list[float] = [0.0] * auxiliary_encoders  # FASTAUXENCODER
        self.auxiliary_bounds = table_bounds("AUXENCODER", table.controller)  # AUXENCODERSCALE is 1: counts
        self.fast_armed = True
        # TIME counts to the top of its range and wraps: 16777215 on NextMove, 65535 on MintDrive (000:16746-16747)
        top = table_bounds("TIME", table.controller).maximum
        self.time_limit = int(top) + 1 if top is not None else TIME_LIMIT

    def time(self) -> int:
        return (self.clock.now - self.time_origin) % self.time_limit

    def register(self, table: KeywordTable) -> None:
        clock = self.clock
        vm = self.vm

        def read_time(_: int | None) -> float:
            clock.changes_next_tick()
            return float(self.time())

        def write_time(_: int | None, value: float) -> None:
            self.time_origin = clock.now - int(value)

        table.register("TIME", read=read_time, write=per_channel(ranged("TIME", table.controller, write_time)))
        table.register("ERR", read=lambda _: vm.err)
        table.register("ERL", read=lambda _: vm.erl)
        table.register("ERRAXIS", read=lambda _: vm.erraxis)
        table.register("LASTERR", read=lambda _: NO_ERROR, command=self._lasterr)
        table.register("AUTO", command=self._auto)
        table.register("INKEY", read=self._inkey)
        table.register("CLS", command=self._cls)
        table.register("BEEP", command=self._beep)
        table.register("BOL", command=self._bol)
        table.register("LOCATE", command=self._locate)
        LineTrace(vm, self.terminal).register(table)
        table.register(
            "NODE",
            read=lambda _: float(self.node),
            write=per_channel(ranged("NODE", table.controller, self._write_node)),
        )
        table.register("COMMS", read=lambda channel: self.comms.read(channel or 0), write=self._write_comms)
        table.register("FASTPOS", read=self._fastpos)
        encoders = channel_range("FASTENCODER", profile(table.controller))
        table.register("FASTENCODER", read=lambda ch: self._fastencoder(ch, encoders))
        table.register("AUXENCODER", read=self.auxiliary_encoder, write=per_channel(self._write_auxiliary))
        table.register("FASTAUXENCODER", read=lambda channel: self.fast_auxiliary[self._auxiliary(channel)])

    def _inkey(self, _: int | None) -> float:
        """Each read takes one key, so after a key the next read differs: PAUSE INKEY = 'Y' reads on through
        the keys typed ahead, and PAUSE INKEY = 0 until they are all taken."""
        code = self.terminal.inkey()
        if code:
            self.clock.changes_next_tick()
        return float(code)

    def _lasterr(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        """LASTERR as a statement displays the error message that last ended a program (the v3 guide's words,
        001:9632-9642; the v4 guide says only that it returns that error, 000:13270-13282). A run starts at
        power-up, so no program has ended on an error before it: the choice is that there is no message to
        display, and the program goes on (BEHAVIOUR.md)."""
        return False

    def _auto(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        """AUTO as the configuration file's first command runs both files at power-up, as a run already starts;
        anywhere else it is ignored (000:6645-6648): either way running it does nothing."""
        return False

    def _cls(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        self.terminal.cls()
        return False

    def _beep(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        self.terminal.beep()
        return False

    def _bol(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        self.terminal.bol()
        return False

    def _locate(self, channels: Channels | None, arguments: tuple[float, ...]) -> bool:
        if len(arguments) != 2:
            raise MintError(2001, detail="LOCATE needs a column and a row")
        self.terminal.locate(int(arguments[0]), int(arguments[1]))
        return False

    def _write_node(self, _: int | None, value: float) -> None:
        """Any node the table gives (0 to 127, 000:14665); one above 15 has no ID character and hears no host packet."""
        self.node = int(value)

    def _write_comms(self, channels: Channels | None, values: tuple[float | None, ...]) -> bool:
        """``COMMS(i) = a, b, ...`` writes consecutive elements, all or none: every address is checked first."""
        address = channels[0] if channels else 0
        writes = [(address + offset, value) for offset, value in enumerate(values) if value is not None]
        for target, _ in writes:
            self.comms.check_write(target)
        for target, value in writes:
            self.comms.write(target, value, external=False)
        return False

    def _axis(self, channel: int | None) -> int:
        number = channel or 0
        if not 0 <= number < len(self.axes):
            raise MintError(2, number)
        return number

    def _auxiliary(self, channel: int | None) -> int:
        number = channel or 0
        if not 0 <= number < len(self.auxiliary_encoders):
            raise MintError(
                INVALID_CHANNEL, number, f"the controller has {len(self.auxiliary_encoders)} auxiliary encoders"
            )
        return number

    def auxiliary_encoder(self, channel: int | None) -> float:
        """AUXENCODER.channel in counts; error 4 on a channel the controller lacks."""
        return self.auxiliary_encoders[self._auxiliary(channel)]

    def _write_auxiliary(self, channel: int | None, value: float) -> None:
        """AUXENCODER = v on a channel the controller has, with v in the table's range (000:6714-6715)."""
        number = self._auxiliary(channel)
        check_range("AUXENCODER", value, self.auxiliary_bounds, number)
        self.auxiliary_encoders[number] = float(int(value))

    def _fastpos(self, channel: int | None) -> float:
        number = self._axis(channel)
        axis = self.axes[number]
        return self.fast_positions[number] / axis.scale

    def _fastencoder(self, channel: int | None, encoders: ChannelRange | None) -> float:
        """The encoder latched, in the units ENCODERSCALE gives (000:10391-10392), as FASTPOS is in SCALE's."""
        if encoders is not None:
            check_channel("FASTENCODER", channel or 0, encoders)
        number = self._axis(channel)
        return self.fast_encoders[number] / self.axes[number].parameters["ENCODERSCALE"]

    def latch_fast_input(self) -> bool:
        """A fast input fired: latch every axis unless the last latch is still being handled (EV-9 RC)."""
        if not self.fast_armed:
            return False
        for number, axis in enumerate(self.axes):
            self.fast_positions[number] = axis.position(axis.measured) * axis.scale  # what POS read then, in counts
            self.fast_encoders[number] = axis.measured - axis.encoder_offset
        self.fast_auxiliary[:] = self.auxiliary_encoders
        return True

    def _system_read(self, address: int) -> float | None:
        element = system_element(address)
        if element is None:
            return None
        unnamed = self._unnamed.get(element.keyword)
        if unnamed is not None:
            return unnamed()
        access = self.table.get(element.keyword)
        if access is None or access.read is None:
            return None
        return access.read(element.channel)

    def _execution_status(self) -> float:
        """2 while the program runs (it is the only reader: a host cannot address it); 0, the command line, after."""
        return 0.0 if self.vm.stopped is not None else 2.0

    def _buffer(self) -> float:
        """The file running: 1 the program, 2 the configuration; 0, the command line, after the run."""
        if self.vm.stopped is not None:
            return 0.0
        return 2.0 if self.vm.in_configuration() else 1.0

    def _line(self) -> float:
        site = self.vm.current_site()
        return float(site.line) if site is not None else 0.0

    def _system_write(self, address: int, value: float) -> bool:
        element = system_element(address)
        if element is None or not element.writable:
            return False
        access = self.table.get(element.keyword)
        if access is None or access.write is None:
            return False
        access.write((element.channel,) if element.channel is not None else None, (value,))
        return True
