"""What a run looks like from outside: the final state of each axis, and answers to expectations."""

from __future__ import annotations

import re

from mintlang.records import record
from mintlang.runtime.controller import Controller
from mintlang.runtime.errors import INVALID_INDEX, MintError, NotSimulated
from mintlang.runtime.motion.axis import Axis
from mintlang.runtime.scenario.expectations import NO_SUCH_THING


@record
class AxisState:
    pos: float
    vel: float
    folerror: float
    axismode: int
    axiserror: int
    axisstatus: int
    dac: float
    idle: bool
    enabled: bool


def axis_state(axis: Axis) -> AxisState:
    return AxisState(
        pos=axis.position(axis.measured),
        vel=axis.velocity_counts() / axis.scale,
        folerror=(axis.demand - axis.measured) / axis.scale,
        axismode=axis.axismode,
        axiserror=axis.axiserror,
        axisstatus=axis.axisstatus,
        dac=axis.dac,
        idle=axis.idle(),
        enabled=axis.enabled,
    )


_TARGET = re.compile(r"(?P<name>[A-Z_][A-Z0-9_]*)(?:\.(?P<channel>\d+))?(?:\((?P<index>-?\d+)\))?")


class Observation:
    """Answers expectations about a running controller (the ``Observer`` of the scenario layer)."""

    def __init__(self, controller: Controller, stopped: str = "") -> None:
        self.c = controller
        self.stopped = stopped

    @property
    def terminal(self) -> str:
        return self.c.terminal.text

    @property
    def printed(self) -> int:
        return self.c.terminal.printed

    def has_printed(self, text: str) -> bool:
        return self.c.terminal.has_printed(text)

    @property
    def axes(self) -> tuple[int, ...]:
        return tuple(range(len(self.c.axes)))

    def value(self, target: str) -> float | None:
        try:
            return self._read(target)
        except (MintError, NotSimulated):  # no value to give (a Mint v3 ERR before any error)
            return None

    def why_unread(self, target: str) -> str:
        try:
            self._read(target)
        except (MintError, NotSimulated) as error:
            return str(error)
        return NO_SUCH_THING

    def _read(self, target: str) -> float | None:
        """The value of ``target``, None when the run has no such thing; raises what reading it raises."""
        found = _TARGET.fullmatch(target)
        if found is None:
            return None
        name, channel, index = found["name"], found["channel"], found["index"]
        access = self.c.table.get(name)
        if name in _CONSUMING:  # reading these changes the controller: look without touching
            return _CONSUMING[name](self.c, int(channel) if channel is not None else None)
        if access is not None and access.indexed_read is not None and index is not None:  # CONTOURPARAMETER.0(0)
            return access.indexed_read(int(channel) if channel is not None else None, (int(index),))
        if access is not None and access.read is not None:
            if index is not None:
                return access.read(int(index))
            return access.read(int(channel) if channel is not None else None)
        names = self.c.linked.names
        identity = name[:10]
        if index is not None:
            slot = names.arrays.get(identity)
            if slot is None:
                return None
            values = self.c.vm.arrays[slot]
            position = int(index)
            if not 1 <= position <= len(values):  # the array is there: the index is what the program would be told
                raise MintError(INVALID_INDEX, detail=f"index {position} outside 1 to {len(values)}")
            return values[position - 1]
        slot = names.scalars.get(identity)
        return self.c.vm.scalars[slot] if slot is not None else None


@record
class Refused:
    """A run the controller refused before its first statement: it printed nothing, and ERR and ERL say why."""

    err: float
    erl: float
    stopped: str = "error"
    terminal: str = ""
    printed: int = 0
    axes: tuple[int, ...] = ()

    def has_printed(self, text: str) -> bool:
        return False

    def value(self, target: str) -> float | None:
        return {"ERR": self.err, "ERL": self.erl}.get(target)

    def why_unread(self, target: str) -> str:
        return NO_SUCH_THING


def _inputs(controller: Controller, channel: int | None) -> float:
    """IN as the program would read it, without clearing the edge latches a read clears."""
    return controller.io.peek(channel)


def _next_key(controller: Controller, channel: int | None) -> float:
    """INKEY as the program would read it, without taking the key."""
    return float(controller.terminal.peek_key())


# Keywords whose read changes state (IO-1, PR-5): an expectation must not change the run it checks.
_CONSUMING = {"IN": _inputs, "INKEY": _next_key}
