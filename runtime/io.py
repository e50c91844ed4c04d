"""Digital inputs and outputs, the relay, the analog inputs and the auxiliary analog outputs (spec §8).

Inputs are sampled once per servo tick from the world's electrical levels.
``INPUTACTIVELEVEL`` turns a level into an active state; edge-triggered inputs
(``INPUTMODE``) latch the edges ``INPUTPOSTRIGGER``/``INPUTNEGTRIGGER`` select,
and reading ``IN`` clears the latches it returns. Outputs and the relays only
record what the program and the drive enables (``drive_enable.py``) drive, for the report and the trace.
An auxiliary DAC (``AUXDAC``, MintDrive and ServoNode 51 only) drives nothing
the simulation models either: it holds what was written, which reading it returns.
A channel (``IN.21``) is numbered across the cards; a whole-card form (``IN``, ``OUT = 5``) addresses
the bank BANK selects (``io_banks.py``).
"""

from __future__ import annotations

from collections.abc import Callable

from mintlang.controllers import ChannelRange, ControllerProfile
from mintlang.runtime.clock import Clock
from mintlang.runtime.errors import INVALID_CHANNEL, OUT_OF_RANGE, MintError
from mintlang.runtime.events import EventClass, Events
from mintlang.runtime.io_banks import BankSelection, with_bit
from mintlang.runtime.keywords import KeywordTable, per_channel
from mintlang.runtime.ranges import ranged, table_default

INVALID_INPUT = 7
INVALID_OUTPUT = 8
ADC_OFF = 4  # ADCMODE's _acOFF on every NextMove (000:6450, 6479)
RELAY0 = 1000  # _RELAY0, the main card's relay as a drive enable output; _RELAY1 and _RELAY2 follow (000:9356-9368)


def _check(channel: int, channels: ChannelRange, code: int) -> int:
    """``channel``, or the controller's error when it is not one of ``channels``."""
    if channel not in channels:
        raise MintError(code, channel, f"channels are {channels}")
    return channel


class DigitalIO:
    def __init__(self, profile: ControllerProfile, clock: Clock, events: Events, banks: BankSelection) -> None:
        self.inputs = profile.digital_inputs
        self.outputs = profile.digital_outputs
        self.banks = banks
        self.adc_channels = profile.adc
        self.clock = clock
        self.events = events
        self.next_input_change: Callable[[], int] = lambda: clock.now + 1  # the world tells when a level may change
        all_inputs = (1 << (self.inputs.high + 1)) - 1
        self.all_inputs = all_inputs
        self.bank_inputs = (1 << banks.banks.inputs) - 1  # the largest whole-card value of a bit per input
        self.levels = 0  # electrical levels, bit per input
        self.active = 0  # active states after INPUTACTIVELEVEL
        self.active_level = all_inputs  # INPUTACTIVELEVEL: 1 = active high (the default)
        self.edge_mode = 0  # INPUTMODE: 1 = edge-triggered
        self.positive_trigger = 0  # INPUTPOSTRIGGER: no edge is detected until one is chosen (000:12353-12356)
        self.negative_trigger = 0  # INPUTNEGTRIGGER
        self.latched = 0  # edges seen and not yet read
        self.levels_only = False  # Mint v3: IN reads the levels, and edges only call #INx (001:4290-4330)
        self.out = 0  # OUT as last written
        self.output_active_level = (1 << (self.outputs.high + 1)) - 1
        self.relay = 0  # a bit per bank's relay
        self.drive_enable_outputs: Callable[[], frozenset[int]] = frozenset  # outputs (or RELAY0) a drive owns
        self.adc = [0.0] * (self.adc_channels.high + 1)
        self.adc_mode = [0.0] * (self.adc_channels.high + 1)  # ADCMODE: 0 at power-up (000:6412-6414)
        self.adc_held: dict[int, float] = {}  # channels turned off, each with the value it read while still on
        self.auxiliary_dac_channels = profile.auxiliary_dac  # None on the NextMoves: AUXDAC is error 17 there
        power_up = table_default("AUXDAC", profile.controller) or 0.0  # 0 (000:6680)
        self.auxiliary_dac = [power_up] * (profile.auxiliary_dac.high + 1 if profile.auxiliary_dac else 0)

    def _input(self, channel: int) -> int:
        return _check(channel, self.inputs, INVALID_INPUT)

    def _output(self, channel: int) -> int:
        return _check(channel, self.outputs, INVALID_OUTPUT)

    # ------------------------------------------------------------------ ticks

    def sample(self, levels: int) -> None:
        """One servo tick of input sampling: edges latch, handlers become pending."""
        previous = self.active
        self.levels = levels
        active = ~(levels ^ self.active_level) & ((1 << (self.inputs.high + 1)) - 1)
        self.active = active
        rising = active & ~previous
        falling = previous & ~active
        edges = ((rising & self.positive_trigger) | (falling & self.negative_trigger)) & self.edge_mode
        self.latched |= edges
        events = self.events
        raising = edges | (active & ~self.edge_mode)  # level inputs raise #INx every tick they are active
        number = 0
        while raising:
            if raising & 1:
                events.raise_input(number)
            raising >>= 1
            number += 1

    def is_active(self, channel: int) -> bool:
        return bool(self.active >> channel & 1)

    def raises_every_tick(self) -> bool:
        """A level-triggered input with a handler is active, so its event arrives on every tick."""
        level = self.active & ~self.edge_mode & self.events.imask
        number = 0
        while level:
            if level & 1 and self.events.has_handler(EventClass.INPUT, number):
                return True
            level >>= 1
            number += 1
        return False

    # --------------------------------------------------------------- keywords

    def register(self, table: KeywordTable) -> None:
        # inputs change only with the world (levels scheduled, position inputs), whose next change _watch reports
        table.register("IN", read=self._read_in, complete_horizon=True)
        table.register("INSTATE", read=self._read_instate, complete_horizon=True)
        for name, attribute in (
            ("INPUTACTIVELEVEL", "active_level"),
            ("INPUTMODE", "edge_mode"),
            ("INPUTPOSTRIGGER", "positive_trigger"),
            ("INPUTNEGTRIGGER", "negative_trigger"),
        ):
            writer = self._bank_writer(attribute, edges_only=attribute.endswith("_trigger"))
            table.register(name, read=self._bank_reader(attribute), write=per_channel(writer))
        table.register("OUT", read=self._read_out, write=per_channel(self._write_out))
        active_level = ranged("OUTPUTACTIVELEVEL", table.controller, self._write_oal)
        table.register(
            "OUTPUTACTIVELEVEL",
            read=lambda _: float(self.banks.outputs(self.output_active_level)),
            write=per_channel(active_level),
        )
        relay = ranged("RELAY", table.controller, self._write_relay)
        table.register("RELAY", read=self._read_relay, write=per_channel(relay))
        table.register("ADC", read=self._read_adc)
        adc_mode = ranged("ADCMODE", table.controller, self._write_adc_mode, channel=self._adc)
        table.register("ADCMODE", read=lambda channel: self.adc_mode[self._adc(channel)], write=per_channel(adc_mode))
        if self.auxiliary_dac_channels is not None:
            self._register_auxiliary_dac(table, self.auxiliary_dac_channels)

    def _watch(self) -> None:
        self.clock.changes_at(self.next_input_change())

    def _read_in(self, channel: int | None) -> float:
        self._watch()
        if channel is None:
            value = self.peek(None)
            self.latched = self.banks.with_inputs(self.latched, 0)
            return value
        value = self.peek(channel)
        self.latched &= ~(1 << channel)
        return value

    def peek(self, channel: int | None) -> float:
        """What reading IN would return, without clearing any latch (for observers, not programs); an input the
        controller lacks is error 7 here too."""
        value = self.active if self.levels_only else (self.active & ~self.edge_mode) | (self.latched & self.edge_mode)
        return float(self.banks.inputs(value) if channel is None else value >> self._input(channel) & 1)

    def _read_instate(self, channel: int | None) -> float:
        self._watch()
        if channel is None:
            return float(self.banks.inputs(self.active))
        return float(self.active >> self._input(channel) & 1)

    def _bank_reader(self, attribute: str) -> Callable[[int | None], float]:
        def read(channel: int | None) -> float:
            value = getattr(self, attribute)
            return float(self.banks.inputs(value) if channel is None else value >> self._input(channel) & 1)

        return read

    def _bank_writer(self, attribute: str, *, edges_only: bool = False) -> Callable[[int | None, float], None]:
        """A writer of the bank's bit pattern, one bit per input; ``edges_only``: the bit of an input INPUTMODE
        does not make edge triggered is left as it is, since setting it "will have no effect" (000:12424-12425,
        12478-12479). The keywords take no channel (``INPUTMODE.1 = 1`` is refused before the program runs, and
        the comms array writes none of them), so the channel is ignored, as IMASK's is.

        The tables print a range, not whole numbers (INPUTMODE 0 to 1048575, 000:12336): a fraction inside it
        is taken by its whole part, as IMASK and OUTPUTACTIVELEVEL take theirs, so ``INPUTMODE = 0.5`` sets no
        bit, and ``mint check``, which checks the printed range, passes it too."""

        def write(_: int | None, value: float) -> None:
            current = getattr(self, attribute)
            if not 0 <= value <= self.bank_inputs:
                raise MintError(OUT_OF_RANGE, detail=f"one bit per input: 0 to {self.bank_inputs}")
            wanted = self.banks.with_inputs(current, int(value))
            settable = self.edge_mode if edges_only else self.all_inputs
            setattr(self, attribute, (current & ~settable) | (wanted & settable))

        return write

    def drive_enable(self, output: int, enabled: bool) -> None:
        """A drive enable output follows its drive: active while enabled (000:9281-9286); -1 drives nothing."""
        if output >= RELAY0:
            self.relay = with_bit(self.relay, output - RELAY0, enabled)
        elif output >= 0:
            self.out = with_bit(self.out, output, enabled)

    def relays(self) -> range:
        """The drive enable outputs that are relays: _RELAY0, and _RELAY1 and _RELAY2 with the cards."""
        return range(RELAY0, RELAY0 + self.banks.banks.count)

    def _driven_bits(self) -> int:
        return sum(1 << output for output in self.drive_enable_outputs() if 0 <= output < RELAY0)

    def _read_out(self, channel: int | None) -> float:
        if channel is None:
            return float(self.banks.outputs(self.out))
        return float(self.out >> self._output(channel) & 1)

    def set_outputs(self, out: int) -> None:
        """The outputs as the program sets them (OUT, MintMT's output moves), but those a drive enable is assigned
        to: the drive's, which keep their state (000:14935-14939, spec IO-3 RC)."""
        driven = self._driven_bits()
        self.out = out & ~driven | self.out & driven

    def _write_out(self, channel: int | None, value: float) -> None:
        limit = 1 << self.banks.banks.outputs  # the table's one range, for OUT and OUT.x alike (000:14887-14913)
        if not 0 <= value < limit:
            raise MintError(OUT_OF_RANGE, detail=f"OUT takes 0 to {limit - 1}")
        if channel is None:
            self.set_outputs(self.banks.with_outputs(self.out, int(value)))
        else:
            self.set_outputs(with_bit(self.out, self._output(channel), bool(value)))

    def _write_oal(self, _: int | None, value: float) -> None:
        self.output_active_level = self.banks.with_outputs(self.output_active_level, int(value))

    def _read_relay(self, _: int | None) -> float:
        return float(self.relay >> self.banks.bank & 1)

    def _write_relay(self, _: int | None, value: float) -> None:
        bank = self.banks.bank
        if RELAY0 + bank not in self.drive_enable_outputs():  # a drive's relay is not RELAY's to set (000:15477-15480)
            self.relay = with_bit(self.relay, bank, bool(value))

    def _adc(self, channel: int | None) -> int:
        """The analog input ``channel`` names (0 when none), or error 4; ADCMODE's channel is ADC's (000:6404, 5620)."""
        return _check(0 if channel is None else channel, self.adc_channels, INVALID_CHANNEL)

    def _read_adc(self, channel: int | None) -> float:
        number = self._adc(channel)
        self._watch()
        return self.adc_reading(number)

    def adc_reading(self, number: int) -> float:
        """What ``ADC`` reads on analog input ``number``: its level, or the value held while it is off."""
        return self.adc_held.get(number, self.adc[number])

    def _register_auxiliary_dac(self, table: KeywordTable, channels: ChannelRange) -> None:
        """AUXDAC.channel, in percent of +10 V, within its table's range (-100 to 100, 000:6673-6686); fractions
        give finer steps (000:4198-4209). No channel is channel 0 (``AUXDAC = 25``, 000:4200); a channel the
        controller lacks is #4, before the value (``ranged``)."""

        def number(channel: int | None) -> int:
            return _check(0 if channel is None else channel, channels, INVALID_CHANNEL)

        def hold(output: int, value: float) -> None:
            self.auxiliary_dac[output] = value

        write = ranged("AUXDAC", table.controller, hold, table.dialect, channel=number)
        table.register("AUXDAC", read=lambda channel: self.auxiliary_dac[number(channel)], write=per_channel(write))

    def _write_adc_mode(self, number: int, mode: float) -> None:
        """A channel turned off reads the last value it read while on, until it is turned on (000:6456-6457, 6495)."""
        if mode == ADC_OFF:
            self.adc_held.setdefault(number, self.adc[number])
        else:
            self.adc_held.pop(number, None)
        self.adc_mode[number] = mode
