"""MintMT's keywords on the v4 machine: each part of the move buffer the notes add, wired to the axes and I/O.

The v4 machine registers its keywords first; MintMT's parts then add theirs
and wrap the v4 move loaders where they act on loading (``TRIGGERMODE``).
The parts that watch each tick's motion are returned as the simulator's
monitors.
"""

from __future__ import annotations

from mintlang.runtime.dialects.mintmt import buffer_size, contouring, identifiers, outputs, triggering
from mintlang.runtime.dialects.mintmt.buffer_low import BufferLowEvent
from mintlang.runtime.dialects.mintmt.output_moves import OutputMoves
from mintlang.runtime.dialects.mintmt.suspend import Suspension
from mintlang.runtime.events import Events
from mintlang.runtime.io import DigitalIO
from mintlang.runtime.keywords import KeywordTable
from mintlang.runtime.monitors import Monitor
from mintlang.runtime.motion.commands import Motion


def install(table: KeywordTable, motion: Motion, io: DigitalIO, events: Events) -> list[Monitor]:
    """Register MintMT's keywords over the v4 ones in ``table``; returns the monitors the simulator must call."""
    buffer_size.install(table, motion)
    trigger_loaded = triggering.install(table, motion)
    contouring.install(table)
    outputs.install(table)
    identifiers.install(table, motion)
    Suspension(motion).register(table)
    buffer_low = BufferLowEvent(motion, events)
    buffer_low.register(table)
    output_moves = OutputMoves(motion, io, trigger_loaded)
    output_moves.register(table)
    return [buffer_low, output_moves]
