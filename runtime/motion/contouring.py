"""CONTOURMODE and CONTOURANGLE: how consecutive path moves blend (spec MP-32, MP-33).

The blending itself lives with the path segments (``paths.Chain``); these
keywords only set what the master axis stores with each MOVE, VECTOR or
CIRCLE as it is loaded (CONTOURMODE) and the corner angle read when two
segments join (CONTOURANGLE, global and not buffered).
"""

from __future__ import annotations

from mintlang.runtime.errors import MintError
from mintlang.runtime.keywords import KeywordTable, per_channel
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.ranges import OUT_OF_RANGE, check_range, table_bounds

MAX_ANGLE = 180.0


def register(table: KeywordTable, motion: Motion) -> None:
    modes = table_bounds("CONTOURMODE", motion.profile.controller)

    def write_mode(channel: int | None, value: float) -> None:
        axis = motion.axis(channel)
        axis.contour_mode = int(check_range("CONTOURMODE", value, modes, axis.number))

    def write_angle(channel: int | None, value: float) -> None:
        axis = motion.axis(channel)
        if not 0.0 <= value <= MAX_ANGLE:
            raise MintError(OUT_OF_RANGE, axis.number, "CONTOURANGLE is 0 to 180 degrees")
        axis.contour_angle = value

    table.register("CONTOURMODE", read=lambda ch: float(motion.axis(ch).contour_mode), write=per_channel(write_mode))
    table.register("CONTOURANGLE", read=lambda ch: motion.axis(ch).contour_angle, write=per_channel(write_angle))
