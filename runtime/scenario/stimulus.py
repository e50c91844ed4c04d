"""The scripted world of a run: plant models, input levels, keys, host packets, and what to expect.

These records are all the simulator reads. Program directives (``REM @sim``)
and scenario files (TOML) both produce them, so the simulator has one shape
to follow whichever way the user wrote the world.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import field, fields
from itertools import chain
from types import MappingProxyType
from typing import Literal, Protocol, TypeVar

from mintlang.records import record
from mintlang.runtime.scenario.expectations import Expectation

PlantModel = Literal["ideal", "stalled", "velamp", "torque"]
EncoderOperator = Literal["<=", ">=", "<", ">"]


@record
class PlantChoice:
    """The plant of one axis (W-1); axes without a choice use ``ideal``."""

    axis: int
    model: PlantModel
    parameters: Mapping[str, float] = field(default_factory=lambda: MappingProxyType({}))


@record
class InputLevel:
    """Digital input ``channel`` is electrically ``level`` from ``time_ms`` on."""

    time_ms: int
    channel: int
    level: int


@record
class PositionInput:
    """Input ``channel`` is high while the physical count of ``axis`` satisfies ``operator counts`` (a limit switch)."""

    channel: int
    axis: int
    operator: EncoderOperator
    counts: int


@record
class IndexPulse:
    """The encoder of ``axis`` gives a Z pulse every ``every_counts``, ``width_counts`` wide."""

    axis: int
    every_counts: int
    width_counts: int


@record
class FastInput:
    """Fast-latch input ``channel`` fires at ``time_ms``."""

    time_ms: int
    channel: int


@record
class AdcLevel:
    """Analog input ``channel`` reads ``percent`` of its range from ``time_ms`` on."""

    time_ms: int
    channel: int
    percent: float


@record
class Keys:
    """``text`` arrives at the terminal at ``time_ms``, one key after another."""

    time_ms: int
    text: str


@record
class HostPacket:
    """Bytes a host sends on the serial line at ``time_ms``."""

    time_ms: int
    data: bytes


@record
class DrivesEnabled:
    """Every drive is enabled when the run starts, as a bench configuration file would leave them.

    A controller powers up with its drives disabled, so the manual's examples,
    which assume a configured machine, would stop at their first move with
    error 40; this record lets them run as printed.
    """


WorldRecord = (
    PlantChoice | InputLevel | PositionInput | IndexPulse | FastInput | AdcLevel | Keys | HostPacket | DrivesEnabled
)


class _Timed(Protocol):
    @property
    def time_ms(self) -> int: ...


_T = TypeVar("_T", bound=_Timed)
_R = TypeVar("_R")


def _in_time_order(records: Iterable[_T]) -> tuple[_T, ...]:
    return tuple(sorted(records, key=lambda record: record.time_ms))  # sorted is stable: equal times keep file order


@record
class Scenario:
    """Everything scripted for one run; timed records in time order, equal times in the order written."""

    plants: tuple[PlantChoice, ...] = ()  # by axis
    inputs: tuple[InputLevel, ...] = ()
    position_inputs: tuple[PositionInput, ...] = ()
    index_pulses: tuple[IndexPulse, ...] = ()  # by axis
    fast_inputs: tuple[FastInput, ...] = ()
    adc: tuple[AdcLevel, ...] = ()
    keys: tuple[Keys, ...] = ()
    host_packets: tuple[HostPacket, ...] = ()
    drives: tuple[DrivesEnabled, ...] = ()  # one record, or none: the drives start disabled
    expectations: tuple[Expectation, ...] = ()  # in the order written

    @property
    def drives_enabled(self) -> bool:
        return bool(self.drives)

    def records(self) -> tuple[WorldRecord | Expectation, ...]:
        """Every record, the world's first; ``scenario_of`` sorts them back into a ``Scenario``."""
        return tuple(chain.from_iterable(getattr(self, part.name) for part in fields(self)))


def scenario_of(records: Iterable[WorldRecord | Expectation]) -> Scenario:
    """Sort records, given in the order written, into a ``Scenario``; a later plant or index of an axis, or
    position of an input, wins."""
    records = tuple(records)

    def kind(cls: type[_R]) -> list[_R]:
        return [record for record in records if isinstance(record, cls)]

    return Scenario(
        plants=tuple(sorted({p.axis: p for p in kind(PlantChoice)}.values(), key=lambda p: p.axis)),
        inputs=_in_time_order(kind(InputLevel)),
        position_inputs=tuple({p.channel: p for p in kind(PositionInput)}.values()),
        index_pulses=tuple(sorted({p.axis: p for p in kind(IndexPulse)}.values(), key=lambda p: p.axis)),
        fast_inputs=_in_time_order(kind(FastInput)),
        adc=_in_time_order(kind(AdcLevel)),
        keys=_in_time_order(kind(Keys)),
        host_packets=_in_time_order(kind(HostPacket)),
        drives=tuple(kind(DrivesEnabled))[:1],
        expectations=tuple(record for record in records if not isinstance(record, WorldRecord)),
    )


def merge(program: Scenario, file: Scenario) -> Scenario:
    """The program's directives overlaid by a scenario file: the file's plant and index choices win per axis, and
    its way of driving an input (levels at times, or a position to follow) per input; levels of an input both
    set at times are all kept, the file's applied after the program's at the same millisecond."""
    driven = {record.channel: type(record) for record in (*file.inputs, *file.position_inputs)}
    kept = (record for record in program.records() if not _driven_otherwise(record, driven))
    return scenario_of((*kept, *file.records()))


def _driven_otherwise(record: WorldRecord | Expectation, driven: Mapping[int, type]) -> bool:
    """Whether ``record`` drives an input that ``driven`` drives the other way: its levels would never show, or
    the position would not be followed."""
    if not isinstance(record, InputLevel | PositionInput):
        return False
    return driven.get(record.channel, type(record)) is not type(record)
