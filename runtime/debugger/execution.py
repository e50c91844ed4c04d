"""The program under the debugger: a simulation on a thread of its own that stops where the editor asks.

The simulator runs unchanged (``run_source``); each compiled operation is
wrapped, as coverage wraps them, so the debugger is asked before every
statement whether to stop there (``Execution._before``). A stop blocks the
simulation thread until the editor sends a command; meanwhile the session's
thread reads the paused state (variables, axes, the stack), which nothing else
touches. Going back (``stepBack``, ``reverseContinue``) takes the run back to
the latest checkpoint before the point wanted (``checkpoints.py``) and runs on
from there (``history.py``, ``stepping.py``); a state that cannot be saved
makes it start again from the beginning instead.
"""

from __future__ import annotations

import threading
from collections import deque
from collections.abc import Callable, Iterator
from contextlib import suppress
from functools import partial
from typing import NoReturn, Protocol

from mintlang.records import record
from mintlang.runtime import snapshot
from mintlang.runtime.controller import Controller
from mintlang.runtime.debugger import stepping
from mintlang.runtime.debugger.breakpoints import Breakpoints
from mintlang.runtime.debugger.checkpoints import INTERVAL, TICK_WORK, Checkpoint, Checkpoints
from mintlang.runtime.debugger.evaluation import Evaluator
from mintlang.runtime.debugger.history import Intervention, Timeline
from mintlang.runtime.debugger.launch import Application
from mintlang.runtime.debugger.stepping import Forward, Point, Scan, cont, reach
from mintlang.runtime.errors import MintError, NotSimulated
from mintlang.runtime.interpreter.vm import Operation, StopReason
from mintlang.runtime.run import RunResult
from mintlang.runtime.scenario import ScenarioFileError
from mintlang.runtime.simulation import Interrupt, Rewind, Simulator, Stop
from mintlang.runtime.trace import Trace

ERRORS = "errors"  # exception filter: stop at every run-time error, even one #ONERROR handles
UNHANDLED = "unhandled"  # exception filter: stop where an error, or a wait nothing can end, ends the run
RECENT = 4096  # points kept to step back to in one re-run: a few hundred kilobytes


class Listener(Protocol):
    """Where the execution reports (the DAP session turns each call into an event)."""

    def stopped(self, reason: str, description: str | None) -> None: ...

    def output(self, text: str, category: str) -> None: ...

    def finished(self, result: RunResult | None, problem: str | None) -> None: ...


@record
class _Rerun:
    plan: Forward | Scan


@record
class _Recent:
    """A point this run passed where stepping may stop, and whether a breakpoint hit there."""

    point: Point
    hit: bool
    generation: int  # of the breakpoints that decided ``hit``


class _Terminate:
    pass


_ENDED_BADLY = frozenset({StopReason.ERROR, StopReason.DEADLOCK})

Plan = Forward | Scan
Command = Forward | _Rerun | _Terminate


class _Abandoned(Interrupt):
    """Ends the run now: a re-run replaces it, or the session ends."""


def _waiting(blocked: tuple[int | None, ...], depth: int, pc: int | None) -> tuple[int | None, ...]:
    """``blocked`` once the statement at ``depth`` has run, ``pc`` if it blocked: the frames above it have
    returned, the ones below it (a PAUSE an event handler interrupted) still wait where they were."""
    below = blocked[:depth] + (None,) * (depth - len(blocked))
    return (*below, pc)


class Execution:
    """Runs ``application`` under ``breakpoints`` and reports to ``listener``."""

    def __init__(self, application: Application, breakpoints: Breakpoints, listener: Listener) -> None:
        self.application = application
        self.breakpoints = breakpoints
        self.listener = listener
        self.timeline = Timeline()
        self.exception_filters: frozenset[str] = frozenset({UNHANDLED})
        self.controller: Controller | None = None
        self.evaluator: Evaluator | None = None
        self.point: Point | None = None  # where the run is paused; None while it runs
        self.ending: Stop | None = None  # how the run ended, while paused where it did
        self._condition = threading.Condition()
        self._command: Command | None = None
        self._pause_requested = False
        self._terminating = False
        self._plan: Plan = cont(-1)
        self._next_plan: Plan | None = None
        self._count = 0
        self._writes = 0
        self._logged_from = 0
        # By frame depth (GOSUBs and handlers open): the statement blocked there, if one is. An event handler
        # that runs while a PAUSE or WAIT waits must not make its next try a new pass over it.
        self._blocked: tuple[int | None, ...] = ()
        self._recent: deque[_Recent] = deque(maxlen=RECENT)  # this run's last points where stepping may stop
        self._checkpoints: Checkpoints | None = Checkpoints()  # None once the state cannot be saved
        self._simulator: Simulator | None = None  # while a run goes, to take it back
        self._ticks = 0  # ticks processed by this run
        self._serial = -1  # the last interval of work this run passed (``checkpoints.py``)
        self._stretch: set[int] = set()  # the statements tried since the latest checkpoint (``Checkpoint.passed``)
        self._thread: threading.Thread | None = None
        self._trace: Trace | None = None  # this run's, when the launch asks for a plot

    # ------------------------------------------------------------ the editor's side

    def start(self, plan: Plan) -> None:
        self._thread = threading.Thread(target=self._main, args=(plan,), name="mint-simulation", daemon=True)
        self._thread.start()

    def _send(self, command: Command) -> None:
        """Resume the paused run with ``command``."""
        with self._condition:
            self._command = command
            self.point = None
            self._condition.notify_all()

    def resume(self, plan: Forward) -> None:
        self._send(plan)

    def rerun(self, plan: Plan) -> None:
        """Go back and run on with ``plan`` (the editor asked to go back): from a checkpoint, else from the start."""
        self._send(_Rerun(plan))

    def step_back(self, at: Point) -> None:
        """Back to the statement before ``at`` in its frame or a caller's: one re-run when that point is among
        the last ``RECENT`` this run passed, else two (a scan finds it first)."""
        for recent in self._earlier(at):
            if recent.point.depth <= at.depth:
                self._back_to(recent.point.count, "step")
                return
        self.rerun(stepping.step_back(at))

    def reverse_continue(self, at: Point) -> None:
        """Back to the last breakpoint hit before ``at``: one re-run when it is among the recent points and the
        breakpoints have not changed since they were passed (else a hit there would not be the same), else two."""
        for recent in self._earlier(at):
            if recent.generation != self.breakpoints.generation:
                break
            if recent.hit:
                self._back_to(recent.point.count, "breakpoint")
                return
        self.rerun(stepping.reverse_continue(at, frozenset(self.breakpoints.by_pc)))

    def _earlier(self, at: Point) -> Iterator[_Recent]:
        return (recent for recent in reversed(self._recent) if recent.point.count < at.count)

    def _back_to(self, count: int, reason: str) -> None:
        self.rerun(self._reach(count, reason))

    def _reach(self, count: int, reason: str) -> Forward:
        """A plan to stop at point ``count``, where what the user changed after it is undone."""
        undone = self.timeline.rewind(count)
        if undone is not None and self._checkpoints is not None:
            self._checkpoints.forget_after(undone)
        return reach(count, reason)

    def pause(self) -> None:
        self._pause_requested = True

    @property
    def checkpoints_kept(self) -> int:
        """How many checkpoints the run holds now: what its memory grows with (``checkpoints.LIMIT`` at most)."""
        return len(self._checkpoints) if self._checkpoints is not None else 0

    def terminate(self) -> None:
        """End the run, paused or not, and wait for its thread to finish."""
        self._terminating = True
        self._send(_Terminate())
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join(timeout=10)

    def intervene(self, description: str, apply: Callable[[Controller], None]) -> None:
        """Change the paused state in a way every re-run through this point repeats."""
        if self.point is None or self.controller is None:
            raise RuntimeError("intervene while the run is paused")
        self.timeline.intervene(Intervention(self.point.count, description, apply), self.controller)
        if self._checkpoints is not None:
            self._checkpoints.forget_after(self.point.count)

    # ------------------------------------------------------- the simulation's side

    def _main(self, plan: Plan) -> None:
        problem = None
        result = None
        try:
            while True:
                result = self._run(plan)
                if self._next_plan is None:
                    break
                plan, self._next_plan = self._next_plan, None
        except ScenarioFileError as error:
            problem = str(error)
        except Exception as error:  # a bug of ours: the session reports it and ends, the editor stays up
            problem = f"internal error: {error!r}"
        self.listener.finished(None if self._terminating else result, problem)

    def _run(self, plan: Plan) -> RunResult:
        self._plan = plan
        self._count = 0
        self._writes = 0
        self._logged_from = self.timeline.points_reached  # log messages at earlier points were shown before
        self._blocked = ()
        self._recent.clear()
        self._ticks = 0
        self._serial = -1
        self._stretch = set()
        if self._checkpoints is not None:
            self._checkpoints = Checkpoints()  # of this run's objects
        plot = self.application.plot
        self._trace = Trace(self._plotted_axes(), None, plotting=True, chosen=False) if plot is not None else None
        record = self._record if plot is not None else None
        result = self.application.run(self._attach, self._echo, record, self._hook)
        self._simulator = None
        if result.refused and self._next_plan is None and not self._terminating:
            self._at_end(result.stop)  # the compiler refused a file: the run ends after the simulation did
        return result

    def _hook(self, simulator: Simulator) -> None:
        self._simulator = simulator
        simulator.before_tick = self._before_tick
        simulator.on_end = self._on_end

    def _before_tick(self, tick: int) -> None:
        """Count the tick; where another interval of work starts, take a checkpoint before it, or go on with the one
        a re-run finds there."""
        work = self._count + TICK_WORK * self._ticks
        self._ticks += 1
        serial = work // INTERVAL
        checkpoints = self._checkpoints
        if serial == self._serial or checkpoints is None:
            return
        self._serial = serial
        taken = checkpoints.numbered(serial)
        if taken is not None:
            self._stretch = taken.passed
        elif checkpoints.wanted(serial):
            self._checkpoint(checkpoints, serial, tick)

    def _checkpoint(self, checkpoints: Checkpoints, serial: int, tick: int) -> None:
        """Take checkpoint number ``serial`` before ``tick``; a state that cannot be saved ends checkpoints."""
        roots = (self._simulator, self._trace)
        try:
            state = snapshot.take([root for root in roots if root is not None], outside=(self,))
        except snapshot.NotSnapshotted as error:
            self._checkpoints = None
            message = f"mint-dap: going back will run the program again from its start: {error}\n"
            self.listener.output(message, "console")
            return
        hits = self.breakpoints.hit_counts()
        ticks = self._ticks - 1
        checkpoint = Checkpoint(serial, tick, self._count, ticks, self._writes, self._blocked, hits, state)
        checkpoints.add(checkpoint)
        self._stretch = checkpoint.passed

    def _go_back(self, plan: Plan) -> NoReturn:
        """Take the run back for ``plan``: to the latest checkpoint before the first point it needs, or to the start
        of a new run when there is none."""
        checkpoints = self._checkpoints if self._simulator is not None else None
        checkpoint = None
        if checkpoints is not None and isinstance(plan, Scan):
            start = checkpoints.search_from(plan.until, plan.pcs)
            if start is None:  # no point before it can be the one wanted
                self._go_back(self._reach(0, "entry"))
            checkpoint, plan.until = start
            plan.since = checkpoint.count
        elif checkpoints is not None:
            checkpoint = checkpoints.latest(plan.after + 1)
        if checkpoint is None:
            self._next_plan = plan
            raise _Abandoned("going back")
        raise Rewind(checkpoint.tick, partial(self._restore, checkpoint, plan))

    def _restore(self, checkpoint: Checkpoint, plan: Plan) -> None:
        """The run as it stood at ``checkpoint``, going on with ``plan``."""
        checkpoint.state.restore()
        self._plan = plan
        self._count = checkpoint.count
        self._ticks = checkpoint.ticks
        self._serial = checkpoint.serial
        self._writes = checkpoint.writes
        self._blocked = checkpoint.blocked
        self._stretch = checkpoint.passed
        self._logged_from = self.timeline.points_reached
        while self._recent and self._recent[-1].point.count >= checkpoint.count:
            self._recent.pop()
        self.breakpoints.restore_hit_counts(checkpoint.hits)

    def _on_end(self, stop: Stop) -> None:
        """The run ended: a scan going back from its end is over; an error or deadlock that ended it stops the
        debugger there first, when the editor asks for that."""
        if self._terminating:
            return
        if isinstance(self._plan, Scan):
            self._scan_done(self._plan)
        self._at_end(stop)

    def _attach(self, controller: Controller) -> None:
        self.controller = controller
        self.evaluator = Evaluator(controller, self.application.dialect)
        self.breakpoints.start_run()
        vm = controller.vm
        vm.operations[:] = [  # the step over a MintMT Event or Startup block is no statement to stop at
            operation if site.declares else self._watched(pc, operation)
            for pc, (operation, site) in enumerate(zip(vm.operations, vm.sites, strict=True))
        ]

    def _watched(self, pc: int, operation: Operation) -> Operation:
        vm = self.controller.vm  # type: ignore[union-attr]

        def watched() -> bool | None:
            point = self._before(pc)
            try:
                blocked = operation()
            except MintError as error:
                if ERRORS in self.exception_filters and isinstance(self._plan, Forward):
                    with suppress(NotSimulated):  # an error the dialect does not number: it ends the run, ERR unset
                        vm.occurred(error, pc)  # ERR and ERL read at the stop as #ONERROR will read them
                    self._stop(point, "exception", error.describe())
                raise
            self._blocked = _waiting(self._blocked, point.depth, pc if blocked else None)
            plan = self._plan
            if blocked and isinstance(plan, Forward) and plan.wake is not None:  # try it again when the plan ends
                vm.wake_at = min(vm.wake_at, max(plan.wake, vm.clock.now + 1))
            return blocked

        return watched

    def _before(self, pc: int) -> Point:
        """Decide, before the statement at ``pc`` runs, whether to stop there; raises to end the run."""
        controller = self.controller
        assert controller is not None and self.evaluator is not None
        frames = controller.vm.frames
        depth = len(frames)
        resumed = depth < len(self._blocked) and self._blocked[depth] == pc
        point = Point(self._count, pc, depth, resumed, controller.clock.now, frames[-1] if frames else None)
        self._count += 1
        self.timeline.reach(point.count)
        for intervention in self.timeline.due(point.count):
            intervention.apply(controller)
        plan = self._plan
        decision = None if point.resumed else self.breakpoints.reached(pc, self.evaluator)
        if not point.resumed:
            self._stretch.add(pc)
            hit = decision is not None and decision.stop
            self._recent.append(_Recent(point, hit, self.breakpoints.generation))
        if decision is not None and decision.log is not None and point.count >= self._logged_from:
            self.listener.output(decision.log, "console")
        if self._terminating:
            raise _Abandoned("the debugging session ended")
        if isinstance(plan, Scan):
            self._scan(plan, point, decision is not None and decision.stop)
            return point
        if self._pause_requested:
            self._pause_requested = False
            self._stop(point, "pause")
        elif plan.breakpoints and decision is not None and decision.stop:
            self._stop(point, "breakpoint", decision.description)
        elif point.count > plan.after and plan.accepts(point):
            self._stop(point, plan.reason)
        return point

    def _scan(self, scan: Scan, point: Point, hit: bool) -> None:
        if point.count >= scan.until:
            self._scan_done(scan)
        if scan.wanted(point, hit):
            scan.found = point.count

    def _scan_done(self, scan: Scan) -> NoReturn:
        """On from ``scan``: to the point it found; else the same search over the points before it; from the
        start, to the start."""
        if scan.found is not None:
            self._go_back(self._reach(scan.found, scan.reason))
        if scan.since > 0:
            self._go_back(scan.earlier())
        self._go_back(self._reach(0, "entry"))

    def _stop(self, point: Point, reason: str, description: str | None = None) -> None:
        """Pause at ``point`` until the editor says what next; a command to go back ends this run."""
        with self._condition:
            self._command = None
            self.point = point
        self._draw(point)
        self.listener.stopped(reason, description)
        with self._condition:
            while self._command is None:
                self._condition.wait()
            command, self._command = self._command, None
        if isinstance(command, _Terminate):
            raise _Abandoned("the debugging session ended")
        if isinstance(command, _Rerun):
            self._go_back(command.plan)
        self._plan = command

    def _at_end(self, stop: Stop) -> None:
        """An error or a deadlock that ended the run stops the debugger there first, when the editor asks for
        that."""
        if stop.reason not in _ENDED_BADLY or UNHANDLED not in self.exception_filters:
            return
        controller = self.controller
        if controller is None:
            return
        vm = controller.vm
        site = vm.stop_site
        pc = vm.sites.index(site) if site is not None and site in vm.sites else len(vm.sites)
        frame = vm.frames[-1] if vm.frames else None
        point = Point(self._count, pc, len(vm.frames), resumed=False, tick=controller.clock.now, frame=frame)
        self.ending = stop
        try:
            self._stop(point, "exception", stop.message)
        except _Abandoned:
            return
        finally:
            self.ending = None

    # ------------------------------------------------------------------- output

    def _plotted_axes(self) -> tuple[int, ...]:
        return tuple(range(self.application.profile.axis_count))

    def _record(self, controller: Controller, tick: int) -> None:
        if self._trace is not None:
            self._trace.record(controller, tick)

    def _draw(self, point: Point) -> None:
        """The run so far, drawn to the launch's ``plot`` image (the axes that moved, and the I/O)."""
        path = self.application.plot
        if path is None or self._trace is None:
            return
        title = f"{self.application.program.name}, stopped at {point.tick} ms"
        try:
            self._trace.plot(path, title)
        except OSError as error:
            self.listener.output(f"mint-dap: cannot write {path}: {error.strerror or error}\n", "stderr")

    def _echo(self, text: str) -> None:
        index = self._writes
        self._writes += 1
        if self.timeline.first_showing(index):
            self.listener.output(text, "stdout")
