"""The simulated controller and its clock: one servo tick after another (spec T-6, the RTM).

Each processed tick samples the world, runs the profiler (every 2 ms), the
servo loop and the error checks, raises timer and comms events and gives the
interpreter a slice. Ticks where nothing can change are skipped: every part
tells when it next can change (a move ending, a scheduled input, a WAIT, the
value a PAUSE condition read), and the clock jumps there. Ticks where only the
program can change, because it works on variables alone, run its slices
without the rest of the tick's work. The results are the same as stepping
every tick; ``every_tick`` (forced by a trace) turns the skipping off, and the
tests compare both.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterable

from mintlang.records import record
from mintlang.runtime.clock import NEVER
from mintlang.runtime.controller import Controller
from mintlang.runtime.errors import MintError, NotSimulated
from mintlang.runtime.events import EventClass
from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.motion.axis import Axis
from mintlang.runtime.motion.homing import still_homing
from mintlang.runtime.motion.idle_masters import master_waited_on

WALL_CHECK_EVERY = 256  # processed ticks between looks at the wall clock
# What a program blocked on INPUT or INKEY waits for, in its deadlock message (mint-run adds how to pipe keys in)
KEYS_NONE_TYPES = "keys that no scenario types (a [[key]] entry, or REM @sim key)"


class Interrupt(Exception):
    """Raised by an observer of the run (the terminal's echo, a tick callback) to end it now; the message says why."""


class Rewind(Exception):
    """Raised by an observer of the run (a debugger going back) to take it back to the start of tick ``tick``:
    ``restore`` puts the state saved there back (``snapshot.py``), and the run goes on from it."""

    def __init__(self, tick: int, restore: Callable[[], None]) -> None:
        super().__init__(f"back to tick {tick}")
        self.tick = tick
        self.restore = restore


@record
class Limits:
    until_ms: int | None = None
    max_wall_s: float | None = None
    realtime: bool = False
    every_tick: bool = False
    slice_statements: int = 20
    host_port: int | None = None
    settle: bool = False  # after END, run the machine on until every axis is idle (see ``Simulator.run``)
    # Ticks at which only the program can change run its slices alone (``Simulator._interpreter_alone``); a
    # debugger that shows the machine where the program stops turns this off, so every tick a statement
    # runs in is up to date.
    program_alone: bool = True
    # With no ``until_ms`` and every expectation timed, end once the last is checked: a test of a program that
    # never ends by itself (a machine's main loop) has nothing left to learn after it (``run.py``).
    end_when_checked: bool = False
    until_message: str | None = None  # the stop's message at ``until_ms`` when --until-ms did not set it


@record
class Stop:
    reason: StopReason
    time_ms: int
    unit: str | None
    line: int | None
    statement: str | None
    message: str


class Simulator:
    """Runs a controller to its end, a limit or a deadlock."""

    def __init__(self, controller: Controller, limits: Limits) -> None:
        self.c = controller
        self.limits = limits
        self.checkpoints: dict[int, list[Callable[[], None]]] = {}
        self.on_tick: Callable[[int], None] | None = None  # per processed tick (trace, progress)
        self.before_tick: Callable[[int], None] | None = None  # before each processed tick (a debugger's checkpoints)
        self.on_end: Callable[[Stop], None] | None = None  # once the run has ended, before ``run`` returns

    def at(self, tick: int, callback: Callable[[], None]) -> None:
        """Call ``callback`` after the work of ``tick`` (expectations at a time)."""
        self.checkpoints.setdefault(tick, []).append(callback)

    def tick(self, t: int) -> None:
        c = self.c
        c.clock.now = t
        c.io.sample(c.world.apply(t))
        axes = [axis for axis in c.axes if not axis.dormant()]
        monitors = c.monitors
        for monitor in monitors:
            monitor.before_motion(t)
        for axis in axes:
            move = axis.move
            if move is not None and t >= move.end:
                axis.complete(t)  # a move that ended between two processed ticks
        if t % 2 == 0:
            start_group = c.motion.start_group
            for axis in axes:
                axis.profiler(t, start_group)
        for monitor in monitors:
            monitor.after_motion(t)
        for axis in axes:
            axis.servo_tick(t)
        if c.world.fast_inputs_due:
            for channel in c.world.fast_inputs_due:
                self.fast_input(channel)
            c.world.fast_inputs_due.clear()
        check = c.supervisor.check
        for axis in axes:
            if axis.enabled or axis.guarded:  # a disabled axis still shows its inputs and has its stop input
                check(axis, t)
        if c.supervisor.stopping:
            c.supervisor.at_rest()
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

    def _step(self, t: int) -> None:
        """Process tick ``t``; a fault the motion raises between two statements ends the run."""
        vm = self.c.vm
        try:
            self.tick(t)
        except MintError as fault:
            vm.halt(fault, vm.current_site())
        except NotSimulated as missing:
            vm.stop(StopReason.ERROR, str(missing))
            vm.on_fatal()
        if self.on_tick is not None:
            self.on_tick(t)

    def _typed(self, t: int, timeout: float | None) -> bool | None:
        """Whether a program that only keys can wake (an INPUT, a PAUSE on INKEY) got some from the keyboard,
        which is waited for here, at most ``timeout`` seconds: what would otherwise be a deadlock. None when
        the time ran out first."""
        vm = self.c.vm
        site = vm.current_site()
        if site is None:
            return False
        line = site.kind == "Input"
        if not (line or (site.kind == "Pause" and vm.awaits_keys)):
            return False
        terminal = self.c.terminal
        if not terminal.await_keys(line=line, timeout=timeout):
            return None if terminal.keyboard is not None and not terminal.keyboard.ended else False
        vm.wake_at = t + 1  # a PAUSE asleep until then reads INKEY again
        return True

    def _wall_left(self, started: float) -> float | None:
        """The real time left before ``--max-wall-s`` for a run that began at ``started`` (None: no limit)."""
        limit = self.limits.max_wall_s
        return None if limit is None else max(limit - (time.perf_counter() - started), 0.0)

    def _deadlock(self, t: int) -> str:
        """Why nothing can wake the program, with the likeliest cause: what it waits on when that is keys (an
        INPUT) or inputs and variables (a PAUSE asleep), else moves waiting on masters nothing moves, a full
        move buffer, or a jog nothing will stop. A move stalled on its master is named only when the program
        may be waiting on it: a PAUSE on an input waits on the input, whatever a follower does."""
        message = "blocked, and nothing scheduled or moving can ever wake the program"
        site = self.c.vm.current_site()
        keys = KEYS_NONE_TYPES
        if self.c.terminal.keyboard is not None:
            keys += " and standard input, which has ended, did not give"
        if site is not None and site.kind == "Input":
            return f"{message}: INPUT waits for {keys}"
        if site is not None and site.kind == "Pause" and self.c.vm.awaits_keys:
            return f"{message}: PAUSE reads INKEY, which waits for {keys}"
        if self.c.vm.asleep:
            return (
                f"{message}: it waits on inputs or variables that no scenario input, event or timer will change"
                " (inputs change only as a scenario says: --stimulus, or REM @sim input)"
            )
        stalled = self._stalled_on_masters(t)
        if stalled:
            waits = ", ".join(f"axis {axis} on {master}" for axis, master in stalled.items())
            return f"{message}: moves wait on the travel of masters at rest that nothing can move ({waits})"
        for axis in self.c.axes:
            if axis.move is None and axis.buffer and axis.buffer_free() <= 0:
                size = int(axis.parameters["MOVEBUFFERSIZE"])
                return f"{message}: the move buffer of axis {axis.number} is full ({size} moves) and no GO started them"
        jogging = [
            axis.number for axis in self.c.axes if axis.move is not None and axis.move.jog and axis.move.end == NEVER
        ]
        if jogging:  # a jog has no end of its own (000:12671-12673): "nothing moving" would mislead
            axes = " and ".join(f"axis {number}" for number in jogging)
            verb = "jogs" if len(jogging) == 1 else "jog"
            return (
                f"blocked: {axes} {verb} until JOG = 0, STOP or an error stops it, and nothing left to run can give one"
            )
        return message

    def _pace(self, t: int, following: int, started: float) -> bool:
        """Wait in real time until tick ``following``; False when the wall-clock limit comes first.

        Nothing changes before ``following``, so the simulated clock may stand anywhere up to it:
        a limit or a Ctrl-C during the wait stops the run at the real time reached.
        """
        limit = self.limits.max_wall_s
        wake = following / 1000.0
        stop_at = wake if limit is None else min(wake, limit)
        try:
            time.sleep(max(stop_at - (time.perf_counter() - started), 0.0))
        except KeyboardInterrupt:
            self.c.clock.now = max(t, min(following - 1, int((time.perf_counter() - started) * 1000)))
            raise
        if stop_at < wake:
            self.c.clock.now = max(t, int(stop_at * 1000))
            self.c.vm.stop(StopReason.WALL_LIMIT, f"ran {stop_at:.1f} s of wall time")
            return False
        return True

    def fast_input(self, channel: int) -> None:
        """A fast input fired: latch the positions just measured and call its handler (EV-9)."""
        c = self.c
        if c.system.latch_fast_input() and c.events.has_handler(EventClass.FASTIN, channel):
            c.system.fast_armed = False
            c.events.raise_event(EventClass.FASTIN, channel)

    def next_change(self, t: int) -> int:
        """The next tick at which anything can change (``NEVER`` when nothing ever will)."""
        vm = self.c.vm
        if vm.progressed or not vm.blocked or self._busy():
            return t + 1
        return self._next_change_besides_the_program(t, vm.wake_at)

    def _busy(self) -> bool:
        """Whether something needs the next tick whatever the program does: an event to dispatch (not while
        the blocked statement holds it pending), an input raising one on every tick, a host port."""
        c = self.c
        return bool(c.events.pending and not c.vm.holding) or c.server is not None or c.io.raises_every_tick()

    def _next_change_besides_the_program(self, t: int, soonest: int, axes: Iterable[Axis] | None = None) -> int:
        """The next tick the world, the timer, a monitor, an axis (of ``axes``, by default every one) or an
        expectation needs, or ``soonest``."""
        c = self.c
        soonest = min(soonest, c.world.next_change(t), c.events.next_timer_event())
        for monitor in c.monitors:
            soonest = min(soonest, monitor.next_required(t))
        for axis in c.axes if axes is None else axes:
            if soonest <= t + 1:
                return t + 1
            soonest = min(soonest, axis.next_required(t))
        if self.checkpoints:
            soonest = min(soonest, *self.checkpoints)
        return max(soonest, t + 1)

    def _interpreter_alone(self, t: int, until: int) -> int:
        """Run the ticks after ``t`` at which only the program can change, its slices alone: the tick to process
        whole next. The program must be running pure statements (``interpreter/purity.py``), which neither
        read nor change anything outside the interpreter, so the rest of those ticks' work would change
        nothing; the slice stops before the first statement that is not pure, and its tick is processed
        whole, the rest of the slice after the tick's other work."""
        c = self.c
        vm = c.vm
        pc = vm.pc
        if vm.stopped is not None or pc >= len(vm.pure) or not vm.pure[pc] or self._busy():
            return t + 1
        quiet = min(self._next_change_besides_the_program(t, until), t + WALL_CHECK_EVERY)
        ticks = quiet - t - 1
        if ticks <= 0:
            return t + 1
        c.clock.now = t + 1
        done = vm.run_ahead(ticks)
        if done == ticks * vm.slice_statements:
            c.clock.now = quiet - 1
            return quiet
        stopped = t + 1 + done // vm.slice_statements  # the tick whose slice it stopped in
        c.clock.now = stopped
        return stopped

    def _moves_end(self, t: int) -> int:
        """The tick the last move still running ends (``NEVER`` when none runs): a program blocked for good
        is a deadlock once the machine has finished what it was doing, as a controller would, not before.
        Nothing else needs those ticks (``Axis.next_required``), so the axes would be left mid-move."""
        ends = [axis.move.end for axis in self.c.axes if axis.move is not None and not axis.held]
        return max(*ends, t + 1) if ends else NEVER

    def _stalled_on_masters(self, t: int) -> dict[int, str]:
        """While the program is blocked: the axes whose moves wait for good on masters nothing can move (FLY,
        FOLLOW or CAM on an idle master), by number with their master, when they are all that still ticks and
        nothing else is scheduled or moving, so that nothing can ever move a master or wake the program. Empty
        otherwise: an event, an input, a host packet, a WAIT or another move may yet change something."""
        c = self.c
        vm = c.vm
        if vm.progressed or not vm.blocked or self._busy():
            return {}
        stalled: dict[int, str] = {}
        for axis in c.axes:
            if axis.move is not None and axis.move.live:
                master = master_waited_on(axis, t)
                if master is None:
                    return {}
                stalled[axis.number] = master
        if not stalled:
            return {}
        others = [axis for axis in c.axes if axis.number not in stalled]
        if any(axis.move is not None and not axis.held for axis in others):
            return {}
        if self._next_change_besides_the_program(t, vm.wake_at, others) < NEVER:
            return {}
        return stalled

    def _settling(self) -> bool:
        """Whether the machine runs on after the program ended: ``Limits.settle`` asks for it, for as long as
        an axis is not idle. Moves outlive the program on a controller; a comparison of two runs whose
        programs end at different times (v3's GO waits, v4's does not) must see them finish."""
        c = self.c
        return self.limits.settle and c.vm.stopped is StopReason.END and not all(axis.idle() for axis in c.axes)

    def run(self) -> Stop:
        """Run to the end, a limit, a deadlock, Ctrl-C or an ``Interrupt``; each becomes the ``Stop`` it returns.

        With ``Limits.settle`` the ticks go on after END while an axis moves (no statement runs; the
        world, the profiler and the servo loop do), up to ``until_ms``; the ``Stop`` is still the END,
        at the time the program ended. A ``Rewind`` raised by an observer, while the run goes or from
        ``on_end``, puts an earlier state back and the run goes on from there."""
        c = self.c
        t = 0
        ended = None  # the time the program ended, when the machine settles after it
        try:
            while True:
                try:
                    ended = self._run_from(t)
                    if self.on_end is not None:
                        self.on_end(self._result(ended))
                    break
                except Rewind as back:
                    back.restore()
                    t = back.tick
        except KeyboardInterrupt:  # stop where the program is, so the report and trace still come out
            c.vm.stop(StopReason.INTERRUPTED, "Ctrl-C")
        except Interrupt as why:
            c.vm.stop(StopReason.INTERRUPTED, str(why))
        finally:
            if c.server is not None:
                c.server.close()
        return self._result(ended)

    def _result(self, ended: int | None) -> Stop:
        c = self.c
        vm = c.vm
        site = vm.stop_site
        return Stop(
            vm.stopped or StopReason.END,
            c.clock.now if ended is None else ended,
            site.unit if site else None,
            site.line if site else None,
            site.text if site else None,
            vm.message,
        )

    def _run_from(self, t: int) -> int | None:
        """Process ticks from ``t`` on until the run stops; the time the program ended, when the machine settled
        after it."""
        c = self.c
        vm = c.vm
        limits = self.limits
        until = limits.until_ms if limits.until_ms is not None else NEVER
        started = time.perf_counter()
        processed = 0
        wall_check = WALL_CHECK_EVERY
        ended = None
        while True:
            if self.before_tick is not None:
                self.before_tick(t)
            self._step(t)
            if vm.stopped is not None:
                if not self._settling():
                    break
                ended = c.clock.now if ended is None else ended
            following = self.next_change(t)
            if following >= NEVER:
                following = self._moves_end(t)
            # at the limit nothing is waited for: the run stops there, as until, blocked or not
            typed = self._typed(t, self._wall_left(started)) if following >= NEVER and t < until else False
            if typed is None:
                vm.stop(StopReason.WALL_LIMIT, f"ran {limits.max_wall_s:.1f} s of wall time waiting for keys")
                break
            if typed:
                following = t + 1
            elif t < until and (following >= NEVER or (following == t + 1 and self._stalled_on_masters(t))):
                vm.stop(StopReason.DEADLOCK, self._deadlock(t))
                break
            if limits.every_tick:
                following = t + 1
            elif following == t + 1 and not vm.blocked and limits.program_alone and not limits.realtime:
                following = self._interpreter_alone(t, until)
                processed += following - t - 1  # the ticks the program ran alone
            if following > until:
                if t < until:  # the state at the limit, as stepping every tick would leave it
                    self._step(until)
                c.clock.now = until
                vm.stop(StopReason.UNTIL, limits.until_message or f"reached --until-ms {until}")
                break
            processed += 1
            if limits.realtime:
                if not self._pace(t, following, started):
                    break
            elif processed >= wall_check:
                wall_check = processed + WALL_CHECK_EVERY
                elapsed = time.perf_counter() - started
                if limits.max_wall_s is not None and elapsed > limits.max_wall_s:
                    homing = "".join(f"; {axis}" for axis in still_homing(c.motion))
                    vm.stop(StopReason.WALL_LIMIT, f"ran {elapsed:.1f} s of wall time{homing}")
                    break
            t = following
        return ended
