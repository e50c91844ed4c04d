"""One side of a verification: a simulator run recorded at every millisecond.

Both runs step every tick (``Limits.every_tick``), so each has a sample at
every millisecond to compare, and the machine runs on after ``END`` until every
axis is idle (``Limits.settle``): a move outlives its program, and v3's waiting
``GO`` ends a program after its moves where v4's ends it before them. What the
program prints is kept apart from what the controller prints about an error
(``ERROR: ...`` in v3, ``R0003: ...`` in v4, X-PRINT): the stops are compared
for themselves.
"""

from __future__ import annotations

import re
from array import array
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

from mintlang.dialect import Dialect
from mintlang.migrate.verification.model import Application, Place
from mintlang.records import record
from mintlang.runtime.controller import Controller
from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import run_source
from mintlang.runtime.scenario.stimulus import Scenario
from mintlang.runtime.simulation import Limits, Stop

_NOT_SIMULATED = re.compile(r"^(.+?) \(.*\) is not simulated by mint-run")


@record
class Piece:
    """Program output: its first character's offset in ``Recording.text``, when and by which line."""

    start: int
    time: int
    place: Place | None


@dataclass(slots=True)
class AxisTrace:
    """POS and VEL as the program would read them (user units), and SCALE, at every millisecond."""

    pos: array[float] = field(default_factory=lambda: array("d"))
    vel: array[float] = field(default_factory=lambda: array("d"))
    scale: array[float] = field(default_factory=lambda: array("d"))


@dataclass(slots=True)
class Recording:
    """A run: its samples (index = simulated millisecond), the program's output and how it stopped."""

    places: list[Place | None] = field(default_factory=list)  # the statement running, None once it ended
    outputs: array[int] = field(default_factory=lambda: array("q"))
    relay: array[int] = field(default_factory=lambda: array("q"))
    axes: list[AxisTrace] = field(default_factory=list)
    text: str = ""
    pieces: list[Piece] = field(default_factory=list)
    stop: Stop | None = None
    refused: bool = False  # the controller's compiler rejected the application: nothing of the program ran

    @property
    def last(self) -> int:
        """The last millisecond sampled (-1 when the run never started)."""
        return len(self.places) - 1

    @property
    def known(self) -> int:
        """The last millisecond whose sample is the whole of it: a run cut short stopped part way through its
        last tick, where the other run may still have printed or moved."""
        return self.last - 1 if self.short is not None else self.last

    @property
    def short(self) -> str | None:
        """Why the simulation could not go on, when that is why it stopped: a keyword it does not model,
        or a limit of the wall clock (the program might have gone on)."""
        stop = self.stop
        if stop is None:
            return None
        found = _NOT_SIMULATED.match(stop.message)
        if stop.reason is StopReason.ERROR and found is not None:
            return stop.message
        if stop.reason in {StopReason.WALL_LIMIT, StopReason.INTERRUPTED}:
            return stop.message
        return None

    @property
    def closed(self) -> bool:
        """Whether the run is over for good (an end, a deadlock, an error): its last state holds for ever."""
        stop = self.stop
        return stop is not None and stop.reason is not StopReason.UNTIL and self.short is None


class _Recorder:
    """The observer of one run: ``on_start``, ``echo`` and ``on_tick`` of ``run_source``."""

    def __init__(self) -> None:
        self.recording = Recording()
        self.controller: Controller | None = None
        self.chunks: list[str] = []
        self.length = 0
        self.announcing = False

    def on_start(self, controller: Controller) -> None:
        self.controller = controller
        self.recording.axes = [AxisTrace() for _ in controller.axes]
        announce = controller.vm.announce

        def announcing(message: str) -> None:  # the controller's error message, not the program's output
            self.announcing = True
            try:
                announce(message)
            finally:
                self.announcing = False

        controller.vm.announce = announcing

    def echo(self, text: str) -> None:
        controller = self.controller
        if controller is None or self.announcing or controller.vm.stopped is not None:
            return  # the controller's message about an error (compared as the run's stop), not the program's output
        site = controller.vm.current_site()
        place = Place(site.unit, site.line) if site is not None else None
        self.recording.pieces.append(Piece(self.length, controller.clock.now, place))
        self.chunks.append(text)
        self.length += len(text)

    def on_tick(self, controller: Controller, tick: int) -> None:
        recording = self.recording
        vm = controller.vm
        site = vm.current_site() if vm.stopped is None else None
        recording.places.append(Place(site.unit, site.line) if site is not None else None)
        recording.outputs.append(controller.io.out)
        recording.relay.append(controller.io.relay)
        for axis, trace in zip(controller.axes, recording.axes, strict=True):
            trace.pos.append(axis.position(axis.measured))
            trace.vel.append(axis.velocity_counts() / axis.scale)
            trace.scale.append(axis.scale)


def record(
    application: Application,
    dialect: Dialect,
    controller: str,
    scenario: Scenario,
    *,
    until_ms: int,
    max_wall_s: float | None,
    functions: Mapping[str, Callable[..., float]] | None = None,
) -> Recording:
    """Run an application to its end (and the machine to rest) or ``until_ms``, recording every millisecond;
    ``functions`` in place of the dialect's (a what-if run, ``explained``)."""
    recorder = _Recorder()
    limits = Limits(until_ms=until_ms, max_wall_s=max_wall_s, every_tick=True, settle=True)
    result = run_source(
        application.program,
        config=application.configuration,
        controller=controller,
        dialect=dialect,
        scenario=scenario,
        limits=limits,
        echo=recorder.echo,
        on_tick=recorder.on_tick,
        on_start=recorder.on_start,
        functions=functions,
    )
    recording = recorder.recording
    recording.text = "".join(recorder.chunks)
    recording.stop = result.stop
    recording.refused = result.refused
    return recording
