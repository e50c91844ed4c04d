"""Moves that wait on an idle master: locked to its travel (FLY, FOLLOW, CAM), they move only when it does.

Such a move is still live (every tick is simulated), but what a program reads
of its axis cannot change before an event or the program itself moves the
master, so a PAUSE on it sleeps. The simulator asks, for a blocked program,
whether such moves are all that still run: if nothing can move their masters,
nothing can ever wake the program, and the run is a deadlock (W-4).
"""

from __future__ import annotations

from mintlang.runtime.keywords import KeywordTable
from mintlang.runtime.motion.axis import Axis
from mintlang.runtime.motion.cams import CamMove
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.motion.flying import LockedMove
from mintlang.runtime.motion.following import VelocityLockedMove
from mintlang.runtime.motion.plants import IdealPlant

_LOCKED = (LockedMove, VelocityLockedMove, CamMove)


def master_waited_on(axis: Axis, now: int) -> str | None:
    """The master ``axis`` waits on for good, by name: its move stands still until that master moves, the master
    is at rest with nothing of its own to move it, and the axis needs no tick for itself; None otherwise."""
    move = axis.move
    if (
        not isinstance(move, _LOCKED)
        or type(axis.plant) is not IdealPlant
        or axis.settling()
        or not move.waits_on_master(now)
    ):
        return None
    return move.link.master.name


def register(table: KeywordTable, motion: Motion) -> None:
    motion.stands_still = lambda axis, now: master_waited_on(axis, now) is not None
