"""Mint v3's home switches and stop input, as the v4 machine's HOMEINPUT and STOPINPUT (``controllers.py``).

``HOME`` runs v4's homing with ``HMSPEED`` and ``BACKOFF``, except that with the switch
already open "the homing routine will immediately terminate" (001:3470); reading ``HOME``
gives the switch (001:3509). ``STOPMODE`` 1 ramps the moves down and lets them go on when
the stop input clears, 2 cancels them (001:4542-4560, 11894-11929).
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType

from mintlang.keyworddb.v3_ranges import AXIS_PARAMETERS
from mintlang.runtime.dialects.v3.handlers import V4Handlers
from mintlang.runtime.errors import OUT_OF_RANGE, MintError
from mintlang.runtime.keywords import Channels, KeywordTable, Values, per_channel
from mintlang.runtime.motion.commands import Motion

STOPMODES: Mapping[float, float] = MappingProxyType({1.0: 1.0, 2.0: 2.0})  # STOPMODE -> STOPINPUTMODE


class V3Switches:
    def __init__(self, motion: Motion, v4: V4Handlers) -> None:
        self.motion = motion
        self.v4 = v4

    def register(self, table: KeywordTable) -> None:
        table.register("HOME", read=self.v4.read("HOMESWITCH"), write=self._home)
        table.register("STOPMODE", read=self._stopmode, write=per_channel(self._write_stopmode))

    def _home(self, channels: Channels | None, values: Values) -> bool:
        """HOME on the axes whose switch is closed; an open one ends its homing at once (001:3470)."""
        switch = self.v4.read("HOMESWITCH")
        axes = channels if channels is not None else (0,)
        closed = [(axis, value) for axis, value in zip(axes, values, strict=False) if not switch(axis)]
        if not closed:
            return False
        return self.v4.write("HOME")(tuple(axis for axis, _ in closed), tuple(value for _, value in closed))

    def _stopmode(self, channel: int | None) -> float:
        return self.motion.axis(channel).parameters["STOPINPUTMODE"]

    def _write_stopmode(self, channel: int | None, value: float) -> None:
        if not AXIS_PARAMETERS["STOPMODE"].holds(value):
            raise MintError(OUT_OF_RANGE, channel, f"STOPMODE = {value:g}")
        self.v4.write_one("STOPINPUTMODE")(channel, STOPMODES[value])
