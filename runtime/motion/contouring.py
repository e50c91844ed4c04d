"""CONTOURMODE and CONTOURANGLE: how consecutive path moves blend (spec MP-32, MP-33).

The blending itself lives with the path segments (``paths.Chain``); these
keywords only set what the master axis stores with each MOVE, VECTOR or
CIRCLE as it is loaded (CONTOURMODE) and the corner angle read when two
segments join (CONTOURANGLE, global and not buffered).
"""

from __future__ import annotations

from mintlang.runtime.keywords import KeywordTable, per_channel
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.ranges import ranged


def register(table: KeywordTable, motion: Motion) -> None:
    def write_mode(number: int, value: float) -> None:
        motion.axis(number).contour_mode = int(value)

    def write_angle(number: int, value: float) -> None:
        motion.axis(number).contour_angle = value

    controller = motion.profile.controller
    mode = ranged("CONTOURMODE", controller, write_mode, channel=motion.axis_number)  # 0, 1 or 3 (NARROWED)
    angle = ranged("CONTOURANGLE", controller, write_angle, channel=motion.axis_number)  # 0 to 180 degrees

    table.register("CONTOURMODE", read=lambda ch: float(motion.axis(ch).contour_mode), write=per_channel(mode))
    table.register("CONTOURANGLE", read=lambda ch: motion.axis(ch).contour_angle, write=per_channel(angle))
