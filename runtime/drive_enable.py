"""Drive enable outputs (IO-7): the output or relay ``DRIVEENABLEOUTPUT`` assigns to an axis follows its drive.

``DRIVEENABLE`` drives the assigned output active or inactive (000:9281-9286), an error that disables
the drive turns it off and ``RESET`` turns it on (000:14935-14939, 15625-15627). While assigned, the
output belongs to the drive: ``OUT`` and ``RELAY`` do not change it (000:15477-15480, spec IO-3 RC).
Assigning an output changes nothing by itself; the next change of the drive drives it (000:2706).
"""

from __future__ import annotations

from collections.abc import Callable

from mintlang.runtime.errors import OUT_OF_RANGE, MintError
from mintlang.runtime.io import RELAY0, DigitalIO
from mintlang.runtime.keywords import Channels, KeywordTable, Values, Writer
from mintlang.runtime.motion.axis import Axis
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.ranges import shown

NO_OUTPUT = -1  # the drive's internal state alone (000:2703-2704)


def install(table: KeywordTable, motion: Motion, io: DigitalIO) -> None:
    """Each axis drives its assigned output; ``DRIVEENABLEOUTPUT`` accepts only what the controller has."""

    def assigned() -> frozenset[int]:
        return frozenset(int(axis.parameters["DRIVEENABLEOUTPUT"]) for axis in motion.axes) - {NO_OUTPUT}

    io.drive_enable_outputs = assigned
    for axis in motion.axes:
        axis.drive_signal = _signal(axis, io)
    access = table.get("DRIVEENABLEOUTPUT")
    if access is not None and access.write is not None:
        table.replace("DRIVEENABLEOUTPUT", write=_checked(access.write, io, motion.axis_number))


def _signal(axis: Axis, io: DigitalIO) -> Callable[[bool], None]:
    return lambda enabled: io.drive_enable(int(axis.parameters["DRIVEENABLEOUTPUT"]), enabled)


def _checked(write: Writer, io: DigitalIO, axis_number: Callable[[int | None], int]) -> Writer:
    """``write`` for values that each name an output (``check_output``), all checked before any is written; an
    axis the controller lacks (error 2) before its value, as ``mint check`` reports them (``ranges.ranged``)."""

    def checked(channels: Channels | None, values: Values) -> bool:
        for place, value in enumerate(values):
            channel = channels[place] if channels is not None and place < len(channels) else None
            if value is not None:
                if channel is not None:
                    axis_number(channel)
                check_output("DRIVEENABLEOUTPUT", value, io, channel)
        return write(channels, values)

    return checked


def check_output(keyword: str, value: float, io: DigitalIO, channel: int | None = None) -> None:
    """Error 3 unless ``value`` is -1, an output or a relay of the controller: an output assignment."""
    if value != NO_OUTPUT and not (value == int(value) and (int(value) in io.outputs or int(value) in io.relays())):
        *others, last = [f"an output {io.outputs}", *(f"_RELAY{number - RELAY0}" for number in io.relays())]
        detail = f"{keyword} = {shown(value)}; it takes -1, {', '.join(others)} or {last}"
        raise MintError(OUT_OF_RANGE, channel, detail)
