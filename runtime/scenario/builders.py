"""Checked construction of every scenario record, shared by the directive and file front ends.

Each builder takes values already read (numbers, text, a ``Phrase``) and
raises ``Invalid`` with a message for the user when a value is out of place,
so the two front ends accept exactly the same worlds and say the same things.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from types import MappingProxyType
from typing import cast, get_args

from mintlang.comms_map import SYSTEM_ELEMENTS
from mintlang.dialect import Dialect
from mintlang.records import record
from mintlang.runtime.comms.packets import encode_read, encode_write
from mintlang.runtime.scenario.expectations import (
    STOP_REASONS,
    Comparison,
    Origin,
    StoppedExpectation,
    TerminalExpectation,
    ValueExpectation,
)
from mintlang.runtime.scenario.phrase import Phrase
from mintlang.runtime.scenario.problems import Invalid
from mintlang.runtime.scenario.stimulus import (
    AdcLevel,
    DrivesEnabled,
    EncoderOperator,
    FastInput,
    HostPacket,
    IndexPulse,
    InputLevel,
    Keys,
    PlantChoice,
    PlantModel,
    PositionInput,
)
from mintlang.runtime.scenario.targets import target


@record
class PlantParameters:
    """The parameters a plant model takes, in the order a directive may give them bare (``velamp 40``)."""

    names: tuple[str, ...]
    required: frozenset[str] = frozenset()
    positive: frozenset[str] = frozenset()


PLANTS: Mapping[PlantModel, PlantParameters] = MappingProxyType(
    {
        "ideal": PlantParameters(()),
        "stalled": PlantParameters(()),
        "velamp": PlantParameters(("k",), required=frozenset({"k"})),
        "torque": PlantParameters(("gain", "viscous", "coulomb"), positive=frozenset({"viscous"})),
    }
)
"""Plant models (W-1) and their parameters; ones not given take the simulator's defaults."""

DEFAULT_NODE = 2  # the controller's NODE at power-up (W-3)
_OPERATORS: tuple[str, ...] = get_args(EncoderOperator)


def _at_least(what: str, value: int, minimum: int, key: str) -> int:
    if value < minimum:
        raise Invalid(f"{what} must be at least {minimum}, not {value}", key=key)
    return value


def _time(time_ms: int) -> int:
    return _at_least("a time in ms", time_ms, 0, "at_ms")


def _channel(channel: int) -> int:
    return _at_least("a channel", channel, 0, "channel")


def _axis(axis: int) -> int:
    return _at_least("an axis", axis, 0, "axis")


def plant(axis: int, model: str, parameters: Mapping[str, float]) -> PlantChoice:
    if model not in PLANTS:
        raise Invalid(f"unknown plant model {model!r} (known: {', '.join(PLANTS)})")
    takes = PLANTS[cast(PlantModel, model)]
    if unknown := sorted(set(parameters) - set(takes.names)):
        known = f"it takes {', '.join(takes.names)}" if takes.names else "it takes none"
        raise Invalid(f"plant {model} has no parameter {', '.join(unknown)} ({known})")
    if missing := sorted(takes.required - set(parameters)):
        raise Invalid(f"plant {model} needs {', '.join(missing)}")
    if negative := [name for name in sorted(takes.positive & set(parameters)) if parameters[name] <= 0]:
        raise Invalid(f"plant {model}: {', '.join(negative)} must be positive")
    return PlantChoice(_axis(axis), cast(PlantModel, model), MappingProxyType(dict(parameters)))


def input_level(time_ms: int, channel: int, level: int) -> InputLevel:
    if level not in (0, 1):
        raise Invalid(f"an input level is 0 or 1, not {level}", key="level")
    return InputLevel(_time(time_ms), _channel(channel), level)


def position_input(channel: int, condition: Phrase) -> PositionInput:
    """An input driven by ``enc <axis> <op> <counts>``, the rest of ``condition`` (a file's ``when``)."""
    try:
        condition.keyword("enc")
        axis = _axis(condition.integer("an axis"))
        operator = condition.choice("a comparison", _OPERATORS)
        counts = condition.integer("a count")
        condition.end()
    except Invalid as problem:
        raise Invalid(str(problem), key="when", column=problem.column) from None
    return PositionInput(_channel(channel), axis, cast(EncoderOperator, operator), counts)


def index_pulse(axis: int, every_counts: int, width_counts: int = 1) -> IndexPulse:
    every = _at_least("the counts between index pulses", every_counts, 1, "every")
    width = _at_least("an index pulse width", width_counts, 1, "width")
    if width >= every:
        raise Invalid(f"an index pulse {width} counts wide does not fit in every {every} counts", key="width")
    return IndexPulse(_axis(axis), every, width)


def fast_input(time_ms: int, channel: int) -> FastInput:
    return FastInput(_time(time_ms), _channel(channel))


def adc_level(time_ms: int, channel: int, percent: float) -> AdcLevel:
    if not -100 <= percent <= 100:
        raise Invalid(f"an ADC level is a percentage from -100 to 100, not {percent:g}", key="percent")
    return AdcLevel(_time(time_ms), _channel(channel), percent)


def keys(time_ms: int, text: str) -> Keys:
    if not text:
        raise Invalid("the keys to type are empty", key="text")
    return Keys(_time(time_ms), text)


def _packet(time_ms: int, encode: Callable[[], bytes]) -> HostPacket:
    at_ms = _time(time_ms)
    try:
        return HostPacket(at_ms, encode())
    except ValueError as problem:  # the encoder's word for an address, node or text a packet cannot carry
        raise Invalid(f"cannot build the host packet: {problem}") from None


def host_write(time_ms: int, address: int, data: str, node: int = DEFAULT_NODE) -> HostPacket:
    """The packet of CM-4 writing ``data`` verbatim (so a test can also send bad data) from ``address`` on."""
    _addressable(address, "write")
    return _packet(time_ms, lambda: encode_write(node, address, data))


def host_read(time_ms: int, address: int, node: int = DEFAULT_NODE) -> HostPacket:
    """The packet of CM-5 reading ``address``."""
    _addressable(address, "read")
    return _packet(time_ms, lambda: encode_read(node, address))


def _addressable(address: int, key: str) -> None:
    """Refuse a system element (100..255, 000:2566-2570) as an address: a packet gives two digits (000:2485-2487),
    and what the element shows is read by an expectation of it instead."""
    if address in SYSTEM_ELEMENTS:
        reach = f"a host packet's address has two digits (0 to 99), so it cannot reach comms element {address}"
        raise Invalid(f"{reach}: to check that system element, expect COMMS({address})", key=key)


def host_raw(time_ms: int, hex_bytes: str) -> HostPacket:
    try:
        data = bytes.fromhex(hex_bytes)
    except ValueError:
        message = f"raw host bytes are pairs of hex digits such as '04 32 32', not {hex_bytes!r}"
        raise Invalid(message, key="raw") from None
    if not data:
        raise Invalid("raw host bytes are empty", key="raw")
    return HostPacket(_time(time_ms), data)


def value_expectation(
    what: str,
    comparison: Comparison,
    value: float,
    *,
    tolerance: float,
    at_ms: int | None,
    origin: Origin,
    dialect: Dialect = Dialect.V4,
) -> ValueExpectation:
    """``what`` is named in the program's ``dialect``."""
    if tolerance < 0:
        raise Invalid(f"a tolerance must be at least 0, not {tolerance:g}", key="tolerance")
    try:
        read = target(what, dialect)
    except Invalid as problem:
        raise Invalid(str(problem), key="what") from None
    return ValueExpectation(read, comparison, value, tolerance, _when(at_ms), origin)


def terminal_expectation(text: str, at_ms: int | None, origin: Origin, *, exact: bool = False) -> TerminalExpectation:
    """Text to find in the terminal output, or (``exact``) all the output: then it may be empty."""
    if not text and not exact:
        raise Invalid("the terminal text to look for is empty", key="terminal_contains")
    return TerminalExpectation(text, _when(at_ms), origin, exact)


def drives_enabled() -> DrivesEnabled:
    return DrivesEnabled()


def stopped_expectation(reason: str, origin: Origin) -> StoppedExpectation:
    if reason not in STOP_REASONS:
        raise Invalid(f"a run stops for one of {', '.join(STOP_REASONS)}, not {reason!r}", key="stopped")
    return StoppedExpectation(reason, origin)


def _when(at_ms: int | None) -> int | None:
    return None if at_ms is None else _time(at_ms)
