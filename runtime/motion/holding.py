"""Holding a positional move at rest and resuming it: a stop input in mode 1 (AX-18) and MintMT's SUSPEND (MT-16).

The move ramps down along its path but stays the axes' move, flagged
``held``: it does not complete, nothing buffered behind it starts, AXISMODE
keeps showing it and IDLE stays 0. A move from the buffer keeps its place
there: MOVEBUFFERFREE does not rise, and a relative move loaded meanwhile
starts from its target, not from where it rests. Released, it ramps back up at ACCEL from
where it stopped and finishes, at the slew speed it would have had.
"""

from __future__ import annotations

from dataclasses import replace

from mintlang.records import record
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.motion.moves import PlannedMove, next_profiler_tick
from mintlang.runtime.motion.profile import plan_move, plan_velocity


@record
class Held:
    move: PlannedMove  # the move as it was
    ramp: PlannedMove  # its ramp to rest, which the axes run while held


def hold(motion: Motion, move: PlannedMove, tick: int, decel: float) -> Held:
    """Ramp ``move`` down at ``decel`` from ``tick`` on every axis running it, and keep it to resume."""
    return hold_on(motion, move, move.stop(tick, decel))


def hold_on(motion: Motion, move: PlannedMove, ramp: PlannedMove) -> Held:
    """Run ``ramp``, a way to rest along ``move``'s path, on every axis running ``move``, and keep it to resume."""
    ramp = replace(ramp, buffered=move.buffered, holds=move)
    for number in move.axes:
        axis = motion.axes[number]
        if axis.move is move:
            axis.move = ramp
            axis.held = True
    return Held(move, ramp)


def release(motion: Motion, held: Held) -> None:
    """Resume a held move from where its ramp has brought it, unless something else took over its axes."""
    move, ramp = held.move, held.ramp
    tick = next_profiler_tick(motion.clock.now)
    members = [motion.axes[number] for number in move.axes]
    for member in members:
        member.held = False
    if not all(member.move in (ramp, None) for member in members):
        return  # something else (a STOP, an error) took over the axes meanwhile
    s, velocity = ramp.path(tick)
    master = motion.axes[move.axes[0]]
    p = master.parameters
    if move.length is not None:
        speed = master.slew_speed() if move.feedrate is None else move.feedrate
        profile = plan_move(move.length - s, speed, p["ACCEL"], p["DECEL"], velocity, sramp=p["SRAMP"])
        resumed = PlannedMove(
            move.mode, move.axes, move.geometry, profile, tick, s, move.length, move.targets, feedrate=move.feedrate
        )
    else:
        profile = plan_velocity(velocity, move.profile.final_velocity, p["ACCEL"], p["DECEL"])
        resumed = PlannedMove(move.mode, move.axes, move.geometry, profile, tick, s, buffered=False, jog=move.jog)
    for index, member in enumerate(members):
        member.begin(resumed, index)
