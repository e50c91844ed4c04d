"""CIRCLEA / CIRCLER: circular interpolation of two axes at the master's path speed (spec MP-15).

A circle is a buffered path segment like a vector: it needs GO, the first
axis is the master whose SPEED, ACCEL and DECEL apply along the arc, and it
may follow or be followed by MOVE, VECTOR and CIRCLE moves (and blend with
them under CONTOURMODE). The arc is computed in counts from its start point,
the exact end of the move loaded before it; its end point is rotated exactly,
so half, quarter and whole turns end where the arithmetic says.
"""

from __future__ import annotations

from collections.abc import Callable

from mintlang.keyworddb.model import CIRCLE_AXES
from mintlang.runtime.errors import MISSING_PARAMETER, TOO_MANY_VALUES, MintError
from mintlang.runtime.keywords import Channels, KeywordTable, Values
from mintlang.runtime.motion.axis import MD_CIRCULAR, MOTION_IN_PROGRESS, Request
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.motion.paths import PATH_MODES, Arc, PathSegment


def circle(motion: Motion, *, relative: bool) -> Callable[[Channels | None, Values], bool]:
    """The writer of CIRCLEA (centre absolute) or CIRCLER (centre relative to the start point).

    Each value is in the keyword's range (000:8163-8165, 8220-8222): the centre's coordinates after their
    axes' SCALE, as for the other moves, and the angle, in degrees, as written.
    """
    keyword = "CIRCLER" if relative else "CIRCLEA"

    def write(channels: Channels | None, values: Values) -> bool:
        axes = motion.addressed(channels)
        if len(axes) < CIRCLE_AXES:
            raise MintError(MISSING_PARAMETER, detail="a circle needs two axes")
        axes = axes[:CIRCLE_AXES]  # the default axes (AXES) may name more; the first two carry the circle
        if len(values) > 3:
            raise MintError(TOO_MANY_VALUES, detail="a circle takes a centre and an angle")
        if len(values) < 3 or None in values:
            raise MintError(MISSING_PARAMETER, detail="a circle needs both centre coordinates and an angle")
        c0, c1, degrees = (value for value in values if value is not None)
        motion.check_values(keyword, [(axes[0], c0), (axes[1], c1)])
        motion.check_values(keyword, [(axes[0], degrees)], scaled=False)
        for axis in axes:
            axis.require_ready()
            if (axis.move is not None and axis.move.mode not in PATH_MODES) or axis.pending_mode:
                raise MintError(MOTION_IN_PROGRESS, axis.number, "a circle follows only MOVE, VECTOR or CIRCLE")
        if any(axis.buffer_free() <= 0 for axis in axes):
            for axis in axes:
                if axis.move is not None:
                    motion.clock.changes_at(axis.move.end)
            return True
        start = (axes[0].reference(), axes[1].reference())
        if relative:
            centre = (start[0] + c0 * axes[0].scale, start[1] + c1 * axes[1].scale)
        else:
            centre = (axes[0].absolute(c0 * axes[0].scale), axes[1].absolute(c1 * axes[1].scale))
        master = axes[0]
        arc = Arc(centre, degrees)
        segment = PathSegment(
            MD_CIRCULAR, (master, axes[1]), master.contour_mode, arc=arc, feedrate=master.loaded_feedrate()
        )
        for axis, target in zip(axes, segment.shape(start).targets, strict=True):
            axis.target = target
        request = Request(MD_CIRCULAR, segment.numbers, segment, ident=master.load_ident)
        for axis in axes:
            axis.buffer.append(request)
        return False

    return write


def register(table: KeywordTable, motion: Motion) -> None:
    table.register("CIRCLEA", write=circle(motion, relative=False))
    table.register("CIRCLER", write=circle(motion, relative=True))
