"""The simulated controller and its clock: one servo tick after another (spec T-6, the RTM).

Each processed tick samples the world, runs the profiler (every 2 ms), the
servo loop and the error checks, raises timer and comms events and gives the
interpreter a slice. Ticks where nothing can change are skipped: every part
tells when it next can change (a move ending, a scheduled input, a WAIT, the
value a PAUSE condition read), and the clock jumps there. The results are the
same as stepping every tick; ``every_tick`` (forced by a trace) turns the
skipping off, and the tests compare both.
"""

from __future__ import annotations

import re
import time
from collections.abc import Callable
from dataclasses import dataclass, field

from mintlang.runtime.clock import NEVER, Clock
from mintlang.runtime.comms.packets import HostEndpoint
from mintlang.runtime.comms.server import HostPortServer
from mintlang.runtime.errors import MintError, NotSimulated
from mintlang.runtime.events import EventClass, Events
from mintlang.runtime.inert import InertSettings
from mintlang.runtime.interpreter.program import Linked, link
from mintlang.runtime.interpreter.vm import Interpreter, StopReason
from mintlang.runtime.io import DigitalIO
from mintlang.runtime.keywords import KeywordTable
from mintlang.runtime.motion.axis import ER_ABORT, Axis
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.motion.extensions import EXTENSIONS
from mintlang.runtime.motion.plants import IdealPlant, Plant, StalledPlant, TorquePlant, VelocityPlant
from mintlang.runtime.motion.stop_input import StopInputs
from mintlang.runtime.motion.supervision import Supervisor
from mintlang.runtime.scenario.stimulus import PlantChoice, Scenario
from mintlang.runtime.system import System
from mintlang.runtime.terminal import Terminal
from mintlang.runtime.world import World
from mintlang.semantic.model import SemanticModel

AXIS_ERROR_PRESENT = 500  # ERR in #ONERROR for an asynchronous motion error (EV-17 RC)
WALL_CHECK_EVERY = 256  # processed ticks between looks at the wall clock


@dataclass(frozen=True, slots=True)
class Limits:
    until_ms: int | None = None
    max_wall_s: float | None = None
    realtime: bool = False
    every_tick: bool = False
    slice_statements: int = 20
    host_port: int | None = None


@dataclass(frozen=True, slots=True)
class AxisState:
    pos: float
    vel: float
    folerror: float
    axismode: int
    axiserror: int
    axisstatus: int
    dac: float
    idle: bool
    enabled: bool


@dataclass(frozen=True, slots=True)
class Stop:
    reason: StopReason
    time_ms: int
    unit: str | None
    line: int | None
    statement: str | None
    message: str


def build_plant(choice: PlantChoice | None) -> Plant:
    if choice is None or choice.model == "ideal":
        return IdealPlant()
    if choice.model == "stalled":
        return StalledPlant()
    if choice.model == "velamp":
        return VelocityPlant(**{"counts_per_second": 1000.0, **choice.parameters})
    return TorquePlant(**dict(choice.parameters))


@dataclass(slots=True)
class Controller:
    """Every part of the simulated controller, wired together."""

    clock: Clock
    table: KeywordTable
    vm: Interpreter
    terminal: Terminal
    axes: list[Axis]
    motion: Motion
    io: DigitalIO
    events: Events
    system: System
    world: World
    supervisor: Supervisor
    linked: Linked
    endpoint: HostEndpoint
    inert: InertSettings
    server: HostPortServer | None = None
    watchers: list[Callable[[int], None]] = field(default_factory=list)


def build_controller(
    model: SemanticModel, scenario: Scenario, limits: Limits, echo: Callable[[str], None] | None = None
) -> Controller:
    """Assemble the controller for ``model``; raises ``NotSimulated`` or ``MintError`` when it cannot compile."""
    profile = model.controller
    clock = Clock()
    table = KeywordTable()
    terminal = Terminal(echo)
    vm = Interpreter(clock, profile.nesting, limits.slice_statements)
    plants = {choice.axis: choice for choice in scenario.plants}
    axes = [
        Axis(number, profile.controller, clock, build_plant(plants.get(number))) for number in range(profile.axis_count)
    ]
    vm.default_axes = tuple(range(len(axes)))
    motion = Motion(axes, profile, clock)
    handlers: dict[str, int] = {}
    events = Events(clock, handlers, lambda message: vm.stop(StopReason.ERROR, message))
    io = DigitalIO(profile, clock, events)
    system = System(clock, vm, terminal, axes, table)
    inert = InertSettings()
    for part in (motion, io, events, system, inert):
        part.register(table)
    for extend in EXTENSIONS:
        extend(table, motion)
    motion.input_active = io.is_active
    motion.index_pulses = {pulse.axis: pulse for pulse in scenario.index_pulses}
    linked = link(model, vm, table, terminal)
    handlers.update(linked.handlers)
    vm.events = events
    endpoint = HostEndpoint(system.comms, lambda: system.node)

    def raise_axis_error(axis: Axis) -> None:
        site = vm.current_site()
        vm.record_error(AXIS_ERROR_PRESENT, site.line if site else 0, axis.number)
        if events.error_handler() is not None:
            events.raise_event(EventClass.ERROR)
            return
        vm.stop(
            StopReason.ERROR, MintError(AXIS_ERROR_PRESENT, axis.number).describe() + f" (AXISERROR {axis.axiserror})"
        )
        abort_all()

    def abort_all() -> None:
        for axis in axes:
            axis.latch(ER_ABORT)
            axis.crash_stop()
            axis.disable()

    def raise_stop() -> None:
        if events.has_handler(EventClass.STOP):
            events.raise_event(EventClass.STOP)

    stop_inputs = StopInputs(motion, raise_stop)
    supervisor = Supervisor(motion, raise_axis_error, stop_inputs)
    motion.on_error = lambda axis, bit: supervisor.error(axis, bit, clock.now)
    vm.on_fatal = abort_all
    events.errors_latched = lambda: any(axis.axiserror for axis in axes)

    events.on_fastin_return = lambda number: setattr(system, "fast_armed", True)
    world = World(scenario, io=io, axes=axes, terminal=terminal, host=endpoint.receive)
    io.next_input_change = lambda: world.next_change(clock.now)
    server = HostPortServer(limits.host_port) if limits.host_port is not None else None
    return Controller(
        clock, table, vm, terminal, axes, motion, io, events, system, world, supervisor, linked, endpoint, inert, server
    )


class Simulator:
    """Runs a controller to its end, a limit or a deadlock."""

    def __init__(self, controller: Controller, limits: Limits) -> None:
        self.c = controller
        self.limits = limits
        self.checkpoints: dict[int, list[Callable[[], None]]] = {}
        self.on_tick: Callable[[int], None] | None = None  # per processed tick (trace, progress)

    def at(self, tick: int, callback: Callable[[], None]) -> None:
        """Call ``callback`` after the work of ``tick`` (expectations at a time)."""
        self.checkpoints.setdefault(tick, []).append(callback)

    def tick(self, t: int) -> None:
        c = self.c
        c.clock.now = t
        c.io.sample(c.world.apply(t))
        axes = [axis for axis in c.axes if not axis.dormant()]
        if t % 2 == 0:
            start_group = c.motion.start_group
            for axis in axes:
                axis.profiler(t, start_group)
        for axis in axes:
            axis.servo_tick(t)
        if c.world.fast_inputs_due:
            for channel in c.world.fast_inputs_due:
                self.fast_input(channel)
            c.world.fast_inputs_due.clear()
        check = c.supervisor.check
        for axis in axes:
            if axis.enabled or axis.parameters["STOPINPUT"] >= 0:
                check(axis, t)
        c.events.tick()
        if c.system.comms.external_writes_pending():
            for address in c.system.comms.take_external_writes():
                if c.events.has_handler(EventClass.COMMS, address):
                    c.events.raise_event(EventClass.COMMS, address)
        if c.server is not None:
            c.server.service(c.endpoint)
        c.vm.run_slice()
        if t in self.checkpoints:
            for callback in self.checkpoints.pop(t):
                callback()

    def fast_input(self, channel: int) -> None:
        """A fast input fired: latch the positions just measured and call its handler (EV-9)."""
        c = self.c
        if c.system.latch_fast_input() and c.events.has_handler(EventClass.FASTIN, channel):
            c.system.fast_armed = False
            c.events.raise_event(EventClass.FASTIN, channel)

    def next_change(self, t: int) -> int:
        """The next tick at which anything can change (``NEVER`` when nothing ever will)."""
        c = self.c
        vm = c.vm
        if vm.progressed or not vm.blocked or c.events.pending or c.server is not None or c.io.raises_every_tick():
            return t + 1
        soonest = min(vm.wake_at, c.world.next_change(t), c.events.next_timer)
        for axis in c.axes:
            if soonest <= t + 1:
                return t + 1
            soonest = min(soonest, axis.next_event(t))
        if self.checkpoints:
            soonest = min(soonest, *self.checkpoints)
        return max(soonest, t + 1)

    def run(self) -> Stop:
        c = self.c
        vm = c.vm
        limits = self.limits
        until = limits.until_ms if limits.until_ms is not None else NEVER
        started = time.perf_counter()
        processed = 0
        t = 0
        try:
            while True:
                try:
                    self.tick(t)
                except (MintError, NotSimulated) as fault:  # raised by the motion between two statements
                    vm.stop(StopReason.ERROR, fault.describe() if isinstance(fault, MintError) else str(fault))
                    vm.on_fatal()
                if self.on_tick is not None:
                    self.on_tick(t)
                if vm.stopped is not None:
                    break
                following = self.next_change(t)
                if following >= NEVER:
                    vm.stop(StopReason.DEADLOCK, "blocked, and nothing scheduled or moving can ever wake the program")
                    break
                if limits.every_tick:
                    following = t + 1
                if following > until:
                    c.clock.now = until
                    vm.stop(StopReason.UNTIL, f"reached --until-ms {until}")
                    break
                processed += 1
                if processed % WALL_CHECK_EVERY == 0 or limits.realtime:
                    elapsed = time.perf_counter() - started
                    if limits.max_wall_s is not None and elapsed > limits.max_wall_s:
                        vm.stop(StopReason.WALL_LIMIT, f"ran {elapsed:.1f} s of wall time")
                        break
                    if limits.realtime and following / 1000.0 > elapsed:
                        time.sleep(following / 1000.0 - elapsed)
                t = following
        finally:
            if c.server is not None:
                c.server.close()
        site = vm.stop_site
        return Stop(
            vm.stopped or StopReason.END,
            c.clock.now,
            site.unit if site else None,
            site.line if site else None,
            site.text if site else None,
            vm.message,
        )


def axis_state(axis: Axis) -> AxisState:
    return AxisState(
        pos=(axis.measured - axis.position_offset) / axis.scale,
        vel=axis.velocity_counts() / axis.scale,
        folerror=(axis.demand - axis.measured) / axis.scale,
        axismode=axis.axismode,
        axiserror=axis.axiserror,
        axisstatus=axis.status | axis.axiserror,
        dac=axis.dac,
        idle=axis.idle(),
        enabled=axis.enabled,
    )


_TARGET = re.compile(r"(?P<name>[A-Z_][A-Z0-9_]*)(?:\.(?P<channel>\d+))?(?:\((?P<index>-?\d+)\))?")


class Observation:
    """Answers expectations about a running controller (the ``Observer`` of the scenario layer)."""

    def __init__(self, controller: Controller, stopped: str = "") -> None:
        self.c = controller
        self.stopped = stopped

    @property
    def terminal(self) -> str:
        return self.c.terminal.text

    @property
    def axes(self) -> tuple[int, ...]:
        return tuple(range(len(self.c.axes)))

    def value(self, target: str) -> float | None:
        found = _TARGET.fullmatch(target)
        if found is None:
            return None
        name, channel, index = found["name"], found["channel"], found["index"]
        access = self.c.table.get(name)
        try:
            if access is not None and access.read is not None:
                if index is not None:
                    return access.read(int(index))
                return access.read(int(channel) if channel is not None else None)
            names = self.c.linked.names
            identity = name[:10]
            if index is not None:
                slot = names.arrays.get(identity)
                if slot is None:
                    return None
                values = self.c.vm.arrays[slot]
                position = int(index)
                return values[position - 1] if 1 <= position <= len(values) else None
            slot = names.scalars.get(identity)
            return self.c.vm.scalars[slot] if slot is not None else None
        except MintError:
            return None
