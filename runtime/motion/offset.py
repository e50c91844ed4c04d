"""OFFSET on an idle axis: a relative positional move shown as _mdOFFSET (spec MP-18).

On NextMove an idle axis takes an OFFSET like a MOVER that needs GO: it
ramps at ACCEL to SPEED above its (zero) base velocity and back down at
DECEL. Only one OFFSET may be loaded or running at a time. Superimposing an
OFFSET on a FOLLOW move needs the following module's cooperation and is not
simulated yet; MintDrive (which starts OFFSET without GO and only on FOLLOW)
is not simulated either.
"""

from __future__ import annotations

from collections.abc import Callable

from mintlang.keyworddb.model import Controller
from mintlang.runtime.errors import MintError, NotSimulated
from mintlang.runtime.keywords import Channels, KeywordTable, Values
from mintlang.runtime.motion.axis import MD_FOLLOW, MD_OFFSET, MOTION_IN_PROGRESS, Axis, Request
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.motion.moves import Geometry, PlannedMove
from mintlang.runtime.motion.profile import plan_move

NEXTMOVES = frozenset({Controller.NEXTMOVE_PCI, Controller.NEXTMOVE_PC, Controller.NEXTMOVE_BX})


def offset(motion: Motion) -> Callable[[Channels | None, Values], bool]:
    def write(channels: Channels | None, values: Values) -> bool:
        pairs = motion._pairs(channels, values)
        for axis, _ in pairs:
            axis.require_ready()
            if axis.axismode & MD_FOLLOW:
                raise NotSimulated("OFFSET", "superimposed on a FOLLOW move")
            if motion.profile.controller not in NEXTMOVES:
                raise NotSimulated("OFFSET", "outside FOLLOW, or without GO, on this controller")
            if axis.busy():
                raise MintError(MOTION_IN_PROGRESS, axis.number, "OFFSET needs an idle axis; one at a time")
        for axis, value in pairs:
            axis.target = axis.hold + value * axis.scale
            axis.buffer.append(Request(MD_OFFSET, (axis.number,), _starter(axis, value * axis.scale)))
        return False

    return write


def _starter(axis: Axis, distance: float) -> Callable[[int], PlannedMove | None]:
    def build(tick: int) -> PlannedMove | None:
        if distance == 0.0:
            return None
        p = axis.parameters
        profile = plan_move(abs(distance), p["SPEED"], p["ACCEL"], p["DECEL"], sramp=p["SRAMP"])
        geometry = Geometry((axis.hold,), (1.0 if distance > 0.0 else -1.0,))
        target = (axis.hold + distance,)
        return PlannedMove(MD_OFFSET, (axis.number,), geometry, profile, tick, 0.0, abs(distance), target)

    return build


def register(table: KeywordTable, motion: Motion) -> None:
    table.register("OFFSET", write=offset(motion))
