"""The simulated controller wired together: axes, I/O, events, terminal, comms, world and the program.

``build_controller`` compiles the application into the interpreter and
connects every part: motion errors reach ``#ONERROR`` (or end the run), stop
inputs reach ``#STOP``, host writes reach ``#COMMSx``, and an unhandled error
aborts every axis, as a NextMove does. A Mint v3 program runs on the same
machine through the v3 layer (``dialects/v3/machine.py``): its keyword table,
its interrupts and its error numbers.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import field, replace
from types import MappingProxyType
from typing import TYPE_CHECKING

from mintlang.controllers import ControllerProfile, io_banks
from mintlang.controllers import profile as profile_of
from mintlang.dialect import Dialect
from mintlang.records import record
from mintlang.runtime import drive_enable, global_error_output
from mintlang.runtime.clock import Clock
from mintlang.runtime.comms.packets import HostEndpoint
from mintlang.runtime.dialects import machine as dialect_machine
from mintlang.runtime.dialects import semantics
from mintlang.runtime.events import MINTDRIVE, NEXTMOVE, NEXTMOVE_MINTMT, EventClass, Events
from mintlang.runtime.inert import InertSettings
from mintlang.runtime.interpreter.program import Linked, link
from mintlang.runtime.interpreter.vm import Interpreter, StopReason
from mintlang.runtime.io import DigitalIO
from mintlang.runtime.io_banks import BankSelection
from mintlang.runtime.keywords import KeywordTable
from mintlang.runtime.monitors import Monitor
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

if TYPE_CHECKING:
    from mintlang.runtime.comms.server import HostPortServer


def build_plant(choice: PlantChoice | None) -> Plant:
    if choice is None or choice.model == "ideal":
        return IdealPlant()
    if choice.model == "stalled":
        return StalledPlant()
    if choice.model == "velamp":
        return VelocityPlant(counts_per_second=choice.parameters["k"])  # the scenario requires k
    return TorquePlant(**dict(choice.parameters))


@record(frozen=False)
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
    monitors: list[Monitor] = field(default_factory=list)  # a dialect's parts that watch each tick's motion


def build_controller(
    model: SemanticModel,
    scenario: Scenario,
    *,
    machine: ControllerProfile | None = None,
    slice_statements: int = 20,
    host_port: int | None = None,
    echo: Callable[[str], None] | None = None,
    functions: Mapping[str, Callable[..., float]] | None = None,
) -> Controller:
    """Assemble the controller for ``model`` (on ``machine``, by default the model's controller as simulated);
    raises ``NotSimulated`` or ``MintError`` when it cannot compile. ``functions`` replace the dialect's
    numeric functions of those names (a what-if run: ``mint-migrate --verify`` gives v4 v3's SIN)."""
    profile = machine or profile_of(model.controller.controller)
    meaning = semantics(model.program.dialect)
    if functions:
        meaning = replace(meaning, functions=MappingProxyType({**meaning.functions, **functions}))
    v3 = meaning.dialect is Dialect.V3
    v3_machine = dialect_machine(Dialect.V3) if v3 else None
    clock = Clock()
    table = KeywordTable(profile.controller, meaning.dialect)
    terminal = Terminal(echo)
    vm = Interpreter(clock, profile.nesting, slice_statements)
    plants = {choice.axis: choice for choice in scenario.plants}
    axes = [
        Axis(number, profile.controller, clock, build_plant(plants.get(number))) for number in range(profile.axis_count)
    ]
    if scenario.drives_enabled:
        for axis in axes:
            axis.enable()
    vm.default_axes = tuple(range(len(axes)))
    motion = Motion(axes, profile, clock)
    handlers: dict[str, int] = {}
    mintmt = meaning.dialect is Dialect.MINTMT
    nextmove = NEXTMOVE_MINTMT if mintmt else NEXTMOVE
    dispatch = v3_machine.DISPATCH if v3 else nextmove if profile.controller.value.startswith("nextmove") else MINTDRIVE
    banks = BankSelection(io_banks(profile))
    events = Events(clock, handlers, lambda message: vm.stop(StopReason.ERROR, message), dispatch, banks)
    io = DigitalIO(profile, clock, events, banks)
    events.imask = io.all_inputs  # IMASK: every input of the controller may raise #INx (EV-7)
    auxiliary = profile.auxiliary_encoders.high + 1 if profile.auxiliary_encoders is not None else 0
    system = System(clock, vm, terminal, axes, table, auxiliary_encoders=auxiliary)
    inert = InertSettings()
    for part in (motion, io, banks, events, system, inert):
        part.register(table)
    for extend in EXTENSIONS:
        extend(table, motion)
    drive_enable.install(table, motion, io)
    global_error_output.install(table, motion, io)
    monitors = dialect_machine(Dialect.MINTMT).install(table, motion, io, events) if mintmt else []
    motion.input_active = io.is_active
    motion.auxiliary_encoder = system.auxiliary_encoder
    motion.index_pulses = {pulse.axis: pulse for pulse in scenario.index_pulses}
    layer = (
        v3_machine.install(
            table, clock=clock, motion=motion, io=io, events_=events, system=system, vm=vm, terminal=terminal
        )
        if v3
        else None
    )
    if layer is not None:
        table, inert = layer.table, layer.inert
    linked = link(model, vm, table, terminal, meaning)
    interrupts = v3_machine.handlers if v3 else dict
    handlers.update(interrupts(linked.handlers))
    events.configuration_handlers = interrupts(linked.configuration_handlers)
    events.in_configuration = vm.in_configuration
    vm.events = events
    vm.errors = meaning.errors(lambda number: axes[number].axiserror)
    endpoint = HostEndpoint(system.comms, lambda: system.node)

    def raise_axis_error(axis: Axis) -> None:
        if layer is not None:
            layer.motion_error(axis)
        site = vm.current_site()
        error = vm.errors.motion_error(axis.number, axis.axiserror)
        if not (events.is_pending(EventClass.ERROR) and 0 <= vm.erraxis < axis.number):
            # several axes in error before #ONERROR runs (ABORT): ERRAXIS names the lowest-numbered
            vm.record_error(vm.errors.number(error) or 0, site.line if site else 0, axis.number)
        if events.has_handler(EventClass.ERROR):
            events.raise_event(EventClass.ERROR)
            return
        vm.halt(error, site)

    def abort_all() -> None:
        for axis in axes:
            axis.latch(ER_ABORT)
            axis.crash_stop()
            axis.disable()

    def raise_stop() -> None:
        if events.has_handler(EventClass.STOP):
            events.raise_event(EventClass.STOP)

    stop_inputs = StopInputs(motion, raise_stop, at_edge=v3)
    supervisor = Supervisor(motion, raise_axis_error, stop_inputs)
    motion.on_error = lambda axis, bit: supervisor.error(axis, bit, clock.now)
    vm.on_fatal = abort_all
    vm.announce = terminal.announce if layer is not None else _shown_while_echoed(terminal.announce, inert)

    def in_error(axis: Axis) -> bool:
        return bool(axis.axiserror & ~supervisor.smart.waiting(axis))

    def onerror_again(number: int) -> None:
        """#ONERROR is called again because an axis is still in error: ERRAXIS names an axis that is
        (000:9933-9936), the one it named if it still is, and ERR its motion error; ERL is left as it was."""
        named = int(vm.erraxis)
        if not (0 <= named < len(axes) and in_error(axes[named])):
            named = number
        error = vm.errors.motion_error(named, axes[named].axiserror)
        vm.record_error(vm.errors.number(error) or 0, int(vm.erl), named)

    events.axis_in_error = lambda: next((axis.number for axis in axes if in_error(axis)), None)
    events.on_onerror_again = onerror_again

    events.on_fastin_return = lambda number: setattr(system, "fast_armed", True)
    wired = profile.fast_inputs if profile.fast_inputs_are_digital_inputs else frozenset()
    world = World(scenario, io=io, axes=axes, terminal=terminal, host=endpoint.receive, fast_digital_inputs=wired)
    io.next_input_change = lambda: world.next_change(clock.now)
    server = _host_port(host_port) if host_port is not None else None
    return Controller(
        clock,
        table,
        vm,
        terminal,
        axes,
        motion,
        io,
        events,
        system,
        world,
        supervisor,
        linked,
        endpoint,
        inert,
        server,
        monitors,
    )


def _shown_while_echoed(announce: Callable[[str], None], inert: InertSettings) -> Callable[[str], None]:
    """The controller's error messages, shown on its terminal only while ECHO's bit 1 is set (000:9549)."""

    def shown(message: str) -> None:
        if inert.shows_errors():
            announce(message)

    return shown


def _host_port(port: int) -> HostPortServer:
    """The host port of a run that asks for one (``--host-port``)."""
    from mintlang.runtime.comms.server import HostPortServer  # noqa: PLC0415 - sockets and a thread: for a host alone

    return HostPortServer(port)
