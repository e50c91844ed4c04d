"""OFFSET: a relative positional move on an idle axis, or on top of a FOLLOW move (spec MP-18).

On NextMove an idle axis takes an OFFSET like a MOVER that needs GO: it
ramps at ACCEL to SPEED above its (zero) base velocity and back down at
DECEL. On a FOLLOW move the same profile runs on top of the master's speed
(``superimposed.py``), also from GO. Only one OFFSET may be loaded or running
at a time, and none while a clutch changes the ratio. MintDrive, which starts OFFSET
without GO and only on FOLLOW, is not simulated.
"""

from __future__ import annotations

from collections.abc import Callable

from mintlang.keyworddb.model import NEXTMOVES
from mintlang.runtime.errors import MintError, NotSimulated
from mintlang.runtime.keywords import Channels, KeywordTable, Values
from mintlang.runtime.motion.axis import MD_FOLLOW, MD_OFFSET, MOTION_IN_PROGRESS, Axis, Request
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.motion.flying import LockedMove
from mintlang.runtime.motion.following import VelocityLockedMove
from mintlang.runtime.motion.moves import Geometry, PlannedMove
from mintlang.runtime.motion.profile import plan_move
from mintlang.runtime.motion.superimposed import Offset


def offset(motion: Motion) -> Callable[[Channels | None, Values], bool]:
    def write(channels: Channels | None, values: Values) -> bool:
        pairs = motion._pairs(channels, values)
        motion.check_values("OFFSET", pairs)
        for axis, _ in pairs:
            axis.require_ready()
            if motion.profile.controller not in NEXTMOVES:
                raise NotSimulated("OFFSET", "without GO, on this controller")
            following = _following(axis)
            if following is None and axis.busy():
                raise MintError(MOTION_IN_PROGRESS, axis.number, "OFFSET needs an idle or following axis")
            if following is not None and (following.offsets.running is not None or axis.buffer):
                raise MintError(MOTION_IN_PROGRESS, axis.number, "one OFFSET at a time")
            if isinstance(following, LockedMove) and following.changing_ratio():
                raise MintError(MOTION_IN_PROGRESS, axis.number, "no OFFSET while a clutch changes the ratio")
        for axis, value in pairs:
            following = _following(axis)
            if following is None:
                axis.target = axis.hold + value * axis.scale
                starter = _starter(axis, value * axis.scale)
                axis.buffer.append(Request(MD_OFFSET, (axis.number,), starter, ident=axis.load_ident))
            else:
                start = _superimpose(axis, following, value * axis.scale)
                axis.buffer.append(Request(MD_OFFSET, (axis.number,), start, onto_running=True, ident=axis.load_ident))
        return False

    return write


def _starter(axis: Axis, distance: float) -> Callable[[int], PlannedMove | None]:
    def build(tick: int) -> PlannedMove | None:
        if distance == 0.0:
            return None
        p = axis.parameters
        profile = plan_move(abs(distance), axis.slew_speed(), p["ACCEL"], p["DECEL"], sramp=p["SRAMP"])
        geometry = Geometry((axis.hold,), (1.0 if distance > 0.0 else -1.0,))
        target = (axis.hold + distance,)
        return PlannedMove(MD_OFFSET, (axis.number,), geometry, profile, tick, 0.0, abs(distance), target)

    return build


def _following(axis: Axis) -> LockedMove | VelocityLockedMove | None:
    """The FOLLOW move an OFFSET would run on."""
    move = axis.move
    if isinstance(move, (LockedMove, VelocityLockedMove)) and move.mode & MD_FOLLOW:
        return move
    return None


def _superimpose(
    axis: Axis, move: LockedMove | VelocityLockedMove, distance: float
) -> Callable[[int], PlannedMove | None]:
    def start(tick: int) -> None:
        if distance == 0.0 or axis.move is not move:
            return  # nothing to add, or the FOLLOW ended before GO
        p = axis.parameters
        profile = plan_move(abs(distance), axis.slew_speed(), p["ACCEL"], p["DECEL"], sramp=p["SRAMP"])
        move.offsets.running = Offset(profile, tick, 1.0 if distance > 0.0 else -1.0)
        move.mode |= MD_OFFSET
        return

    return start


def register(table: KeywordTable, motion: Motion) -> None:
    table.register("OFFSET", write=offset(motion))
