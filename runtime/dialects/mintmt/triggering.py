"""TRIGGERMODE: MintMT's automatic triggering, a move starting as soon as it is loaded (004:56-61).

The note shows one value, 0, which enables it; every axis starts without it
(moves wait for ``GO``, as in v4) and any other value turns it off again
(mintlang/MINTMT.md, MT-10). A move loaded on an axis with automatic triggering
is started as ``GO`` on the axes it was written for would start it.
"""

from __future__ import annotations

from collections.abc import Callable

from mintlang.runtime.keywords import Channels, KeywordTable, Values, Writer
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.ranges import check_range, table_bounds

AUTOMATIC = 0.0
WAIT_FOR_GO = 1.0  # the power-up value: any value but 0 (MT-10)
# the moves GO starts (000:11052-11070) that the simulator loads: HTA and SPLINE stop the run as not simulated
LOADING = ("CAM", "CIRCLEA", "CIRCLER", "FLY", "INCA", "INCR", "MOVEA", "MOVER", "OFFSET", "VECTORA", "VECTORR")


def install(table: KeywordTable, motion: Motion) -> Callable[[Channels | None], None]:
    """TRIGGERMODE, and every move-loading keyword of ``LOADING`` the table has, triggering where it is on;
    returns what starts the moves just loaded on the axes named, where triggering is automatic."""
    modes = dict.fromkeys(range(len(motion.axes)), WAIT_FOR_GO)
    limits = table_bounds("TRIGGERMODE", table.controller, table.dialect)  # MT-10: whole numbers

    def read(channel: int | None) -> float:
        return modes[motion.axis(channel).number]

    def write(channels: Channels | None, values: Values) -> bool:
        for axis, value in zip(motion.addressed(channels), values, strict=False):
            if value is not None:
                modes[axis.number] = check_range("TRIGGERMODE", value, limits, axis.number)
        return False

    def loaded(channels: Channels | None) -> None:
        # only what went into a buffer: a FLY a FOLLOWMODE 3 clutch takes, or a MOVEA to where the axis stands,
        # leaves nothing there to start, and GO on a following axis would be error 10
        automatic = [
            axis.number for axis in motion.addressed(channels) if modes[axis.number] == AUTOMATIC and axis.buffer
        ]
        if automatic:
            motion.go(tuple(automatic), ())

    table.register("TRIGGERMODE", read=read, write=write)
    for name in LOADING:
        access = table.get(name)
        if access is not None and access.write is not None:
            table.replace(name, write=_triggering(access.write, loaded))
    return loaded


def _triggering(load: Writer, loaded: Callable[[Channels | None], None]) -> Writer:
    def write(channels: Channels | None, values: Values) -> bool:
        if load(channels, values):
            return True  # waiting for room in the buffer: nothing was loaded yet
        loaded(channels)
        return False

    return write
