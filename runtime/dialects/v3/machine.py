"""A v3 controller assembled on the v4 machine: its keyword table, its interrupts, its errors."""

from __future__ import annotations

from collections.abc import Callable

from mintlang.records import record
from mintlang.runtime.clock import Clock
from mintlang.runtime.dialects.v3 import events
from mintlang.runtime.dialects.v3.handlers import V4Handlers
from mintlang.runtime.dialects.v3.keywords import V3KeywordTable, inert_settings
from mintlang.runtime.dialects.v3.motion import V3Motion
from mintlang.runtime.dialects.v3.recovery import V3Recovery
from mintlang.runtime.dialects.v3.switches import V3Switches
from mintlang.runtime.dialects.v3.system import V3System
from mintlang.runtime.events import Events
from mintlang.runtime.inert import InertSettings
from mintlang.runtime.interpreter.vm import Interpreter
from mintlang.runtime.io import DigitalIO
from mintlang.runtime.keywords import KeywordTable
from mintlang.runtime.motion.axis import Axis
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.system import System
from mintlang.runtime.terminal import Terminal

DISPATCH = events.DISPATCH  # how the interrupts are dispatched
handlers = events.handlers  # which labels are interrupt routines


@record
class V3Controller:
    """What the v3 layer gives the controller: its keywords, its inert settings, and what a motion error adds."""

    table: KeywordTable
    inert: InertSettings
    motion_error: Callable[[Axis], None]  # after the failing axis's own default action


def install(
    v4: KeywordTable,
    *,
    clock: Clock,
    motion: Motion,
    io: DigitalIO,
    events_: Events,
    system: System,
    vm: Interpreter,
    terminal: Terminal,
) -> V3Controller:
    """The v3 keyword table over the v4 handlers in ``v4``, with the v3 power-up state of the parts."""
    table = V3KeywordTable(v4.controller, len(motion.axes))
    handlers = V4Handlers(v4)
    recovery = V3Recovery(motion, handlers)
    controller_wide = V3System(handlers, clock=clock, axes=motion.axes, io=io, events=events_, system=system, vm=vm)
    for part in (V3Motion(motion, handlers), V3Switches(motion, handlers), recovery):
        part.register(table)
    controller_wide.register(table, terminal)
    recovery.on_reset.append(controller_wide.reset)
    events.falling_edges(io)
    return V3Controller(table, inert_settings(table), recovery.motion_error)
