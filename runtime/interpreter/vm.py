"""The interpreter: runs compiled statements in slices between servo ticks.

A program is a flat list of operations (functions built once by the compiler);
each returns ``True`` when it has to block, and is then retried in a later
slice. Control flow is the program counter ``pc``, the GOSUB/event frame stack
and the loop stack, which also enforce the controller's nesting limits (error
2015). Run-time errors become ``ERR``/``ERL``/``ERRAXIS`` and a call of
``#ONERROR``, or end the run.
"""

from __future__ import annotations

from collections.abc import Callable
from enum import StrEnum
from typing import Protocol

from mintlang.controllers import NestingLimits
from mintlang.records import record
from mintlang.runtime.clock import NEVER, Clock
from mintlang.runtime.errors import ErrorStyle, MintError, NotSimulated, V4Errors
from mintlang.semantic.blocks import BlockKind, nesting_problem

Operation = Callable[[], bool | None]

STACK_OVERFLOW = 2015
RETURN_WITHOUT_GOSUB = 2010


class StopReason(StrEnum):
    END = "end"
    ERROR = "error"
    UNTIL = "until"
    DEADLOCK = "deadlock"
    WALL_LIMIT = "wall-limit"
    INTERRUPTED = "interrupted"  # Ctrl-C, or whoever reads the output went away


@record
class Site:
    """Where an operation came from, for ``ERL`` and for reports."""

    unit: str  # "program" or "configuration"
    line: int
    text: str  # the statement as written
    kind: str = ""  # the statement's syntax node (IfDo, Pause …): coverage tells branches by it
    # A MintMT Event or Startup line: the controller enters its block; the code around it only steps over it
    # (MT-7), so it is no statement a reader sees run, stops at or covers, as a v4 label line holds none.
    declares: bool = False


@record(frozen=False)
class Loop:
    """A block open on the controller's stack: a loop, or an IF .. DO whose branch is running.

    Leaving a block with GOTO leaves its entry behind, and done again and again
    that overflows the stack (000:11199-11215): the entries count toward the
    nesting limits of section 3.9 until the block that holds them ends.
    """

    opener: int  # pc of the FOR/WHILE/REPEAT/LOOP/IF .. DO operation
    exit: int  # pc after the closer, where EXIT continues
    kind: BlockKind
    slot: int = -1  # FOR: the loop variable
    end: float = 0.0
    step: float = 0.0


@record
class Recovery:
    """Where ``RETURN`` from ``#ONERROR`` resumes after an error in a block statement: never inside its block."""

    resume: int  # the pc after the whole construct (for a loop closer: the loop's exit)
    loop: int | None = None  # the opener whose loop entry the error leaves


@record(frozen=False)
class Frame:
    return_pc: int
    loops: int  # loop stack depth at the call: loops left open inside a subroutine end with it
    rank: int | None  # the event class rank of a handler frame, None for GOSUB
    entered_at: int  # the statement a call stack shows for the caller: the GOSUB, the failing one for #ONERROR
    target: int  # the code called, a subroutine's or handler's first statement: what a call stack names the frame by
    ending: MintError | None = None  # #ONERROR called for an error that ends the run when it returns


class EventSource(Protocol):
    """What the interpreter needs from the event system."""

    pending: int  # non-zero while some event may be dispatched

    def take(self, running_rank: int | None) -> tuple[int, int] | None:
        """The (rank, handler pc) of the event to run now, given the rank of the running handler."""
        ...

    def handler_returned(self, rank: int) -> None: ...

    def error_handler(self) -> int | None:
        """The pc of the ``#ONERROR`` that serves a synchronous error now, if any."""
        ...


class Interpreter:
    """The state of a running program; the compiler fills ``operations`` and ``sites``."""

    def __init__(self, clock: Clock, nesting: NestingLimits, slice_statements: int = 20) -> None:
        self.clock = clock
        self.nesting = nesting  # the controller's limits (v4 guide 3.9); events count as GOSUB calls
        self.slice_statements = slice_statements  # statements per servo tick (RTM RC K = 20)
        self.operations: list[Operation] = []
        self.sites: list[Site] = []
        self.pure = bytearray()  # per operation: 1 if it acts on the interpreter alone (``purity.py``)
        self.steps_over = bytearray()  # per operation: 1 if it steps over a MintMT block (``Site.declares``)
        # per operation: the generated passes of the loop whose first statement it is (``compiled_loops.py``)
        self.compiled_loops: list[Callable[[int], int] | None] = []
        self.ahead = 0  # statements of the current tick already run by ``run_ahead``
        self.program_start = 0  # where the program file begins, after the configuration file
        self.recoveries: dict[int, Recovery] = {}  # pc of a block statement -> how an error in it resumes
        self.scalars: list[float] = []
        self.arrays: list[list[float]] = []
        self.pc = 0
        self.ran: int | None = None  # the last statement run: where a program that runs off its end ended
        self.frames: list[Frame] = []
        self.loops: list[Loop] = []
        self.default_axes: tuple[int, ...] = (0,)
        self.waits: dict[tuple[int, int], int] = {}  # (frame depth, pc) -> tick a WAIT ends
        self.blocked = False
        self.progressed = False  # the last slice completed a statement: anything may have changed
        self.wake_at = NEVER  # while blocked: the earliest tick the blocking statement may pass
        self.asleep = False  # while blocked: nothing but an event can let it pass before wake_at
        self.awaits_keys = False  # the last PAUSE to block reads INKEY: only a key can let it pass
        # the blocked statement keeps events pending until it completes: only GO, PAUSE and WAIT let an
        # event in before they end (000:4397-4399); INPUT waiting for its line does not
        self.holding = False
        self.sleeps = True  # whether an asleep statement is left alone until wake_at (not when every tick is run)
        self.stopped: StopReason | None = None
        self.stop_site: Site | None = None
        self.message = ""  # why the run ended, for an error
        self.err = -1.0
        self.erl = 0.0
        self.erraxis = -1.0
        self.on_fatal: Callable[[], None] = lambda: None  # an unhandled error aborts every axis
        self.announce: Callable[[str], None] = lambda message: None  # the controller prints its error message
        self.events: EventSource | None = None
        self.executing: int | None = None  # the pc of the operation running now, outside a slice None
        self.errors: ErrorStyle = V4Errors()  # how the dialect numbers errors and words their messages

    # ------------------------------------------------------------------ running

    def run_slice(self) -> None:
        """Run up to ``slice_statements`` statements, or until the program blocks or ends.

        A statement blocked asleep (a PAUSE on inputs and variables) is not tried again before its
        ``wake_at`` unless an event is pending: what it reads cannot have changed.
        """
        events = self.events
        pending = events is not None and events.pending
        if self.blocked and self.asleep and self.sleeps and self.clock.now < self.wake_at and not pending:
            self.progressed = False
            return
        self.asleep = False
        operations, compiled_loops, steps_over = self.operations, self.compiled_loops, self.steps_over
        count = len(operations)
        budget = self.slice_statements - self.ahead
        self.blocked = False
        last = self.ran
        try:
            while budget > 0 and self.stopped is None:
                if events is not None and events.pending and not self.holding:
                    self.executing = None
                    self._dispatch(events)
                pc = self.pc
                if pc >= count:
                    self.executing = None
                    self.ran = last
                    self._finish()
                    return
                passes = compiled_loops[pc]  # pure statements: no event becomes pending while they run
                if passes is not None:
                    ran = passes(budget)
                    if ran:
                        budget -= ran
                        last = self.ran
                        continue
                self.pc = pc + 1
                self.executing = pc
                if not steps_over[pc]:
                    last = pc
                try:
                    if operations[pc]():
                        self.pc = pc
                        self.blocked = True
                        return
                except MintError as error:
                    self.fail(error, pc)
                except NotSimulated as missing:
                    self.not_simulated(missing)
                    return
                budget -= 1  # a statement completed, or failed into ERR and #ONERROR
        finally:
            self.executing = None
            self.ran = last
            self.progressed = budget < self.slice_statements
            self.ahead = 0

    def run_ahead(self, ticks: int = 1) -> int:
        """Run the slices of ``ticks`` ticks at which nothing but the interpreter can change: pure statements only.

        Stops before the first statement that is not pure, or that fails (it has changed nothing, and runs
        again in the tick processed whole); returns how many ran, every slice's statements when none stopped
        it. A loop compiled whole runs its passes in one call (``compiled_loops.py``). No step over a MintMT
        block is pure: each statement run here is one a reader sees run.
        """
        operations, pure, compiled_loops = self.operations, self.pure, self.compiled_loops
        count = len(operations)
        done = 0
        budget = self.slice_statements * ticks
        last = self.ran
        try:
            while done < budget:
                pc = self.pc
                if pc >= count or not pure[pc]:
                    break
                passes = compiled_loops[pc]
                if passes is not None:
                    ran = passes(budget - done)
                    if ran:
                        done += ran
                        last = self.ran
                        continue
                self.pc = pc + 1
                self.executing = pc
                try:
                    operations[pc]()  # a pure statement never blocks
                except (MintError, NotSimulated):
                    self.pc = pc
                    break
                last = pc
                done += 1
        finally:
            self.executing = None
            self.ran = last
            self.ahead = done % self.slice_statements if done < budget else 0
        return done

    def current_site(self) -> Site | None:
        """The statement running now, or between slices the one the program continues with; once the program
        has run off its end, the last statement it ran (a MintMT block stepped over is none: MT-7)."""
        sites = self.sites
        pc = self.executing if self.executing is not None else self.pc
        if pc < len(sites):
            return sites[pc]
        return sites[self.ran] if self.ran is not None else None

    def stop(self, reason: StopReason, message: str = "", site: Site | None = None) -> None:
        """End the run, at ``site`` (by default the statement running now)."""
        if self.stopped is None:
            self.stopped = reason
            self.stop_site = site or self.current_site()
            self.message = message

    def not_simulated(self, missing: NotSimulated) -> None:
        """The run meets what the simulator does not model: it stops there, and says what."""
        self.stop(StopReason.ERROR, str(missing))
        self.on_fatal()

    def _finish(self) -> None:
        self.stop(StopReason.END)

    # ------------------------------------------------------------- subroutines

    def call(self, target: int, rank: int | None = None, return_pc: int | None = None, at: int | None = None) -> None:
        """Enter the code at ``target``, to return to ``return_pc`` (by default the statement next to run).
        ``at`` is the statement the caller is shown at: by default the GOSUB that calls (the statement before
        the one next to run), or for an event the statement it broke in before."""
        if len(self.frames) >= self.nesting.gosub:
            raise MintError(STACK_OVERFLOW, detail=f"more than {self.nesting.gosub} nested GOSUB calls and events")
        self._enter(target, rank, return_pc, at)

    def _enter(self, target: int, rank: int | None, return_pc: int | None, at: int | None) -> None:
        """``call`` past the check of the GOSUB stack's depth."""
        back = self.pc if return_pc is None else return_pc
        shown = at if at is not None else back if rank is not None else self.pc - 1
        self.frames.append(Frame(back, len(self.loops), rank, shown, target))
        self.pc = target

    def return_(self) -> None:
        if not self.frames:
            raise MintError(RETURN_WITHOUT_GOSUB)
        frame = self.frames.pop()
        del self.loops[frame.loops :]
        self.pc = frame.return_pc
        if frame.rank is not None and self.events is not None:
            self.events.handler_returned(frame.rank)
        if frame.ending is not None:  # back at the failing statement, which the run ends on
            self.halt(frame.ending, self.sites[frame.return_pc])

    def running_rank(self) -> int | None:
        """The rank of the innermost running event handler (lower ranks pre-empt higher ones)."""
        for frame in reversed(self.frames):
            if frame.rank is not None:
                return frame.rank
        return None

    def in_configuration(self) -> bool:
        """Whether the statement running (or, between statements, the next one) is in the configuration file."""
        pc = self.executing if self.executing is not None else self.pc
        return pc < self.program_start

    def _dispatch(self, events: EventSource) -> None:
        if len(self.frames) >= self.nesting.gosub:
            return  # an event stays pending while the GOSUB stack is full (EV-6)
        chosen = events.take(self.running_rank())
        if chosen is not None:
            rank, handler = chosen
            self.call(handler, rank)

    # ------------------------------------------------------------------- loops

    def enter_loop(self, loop: Loop) -> None:
        """Push a block entered now; one more than the controller's stack holds is a stack overflow."""
        loops = self.loops
        open_ = dict.fromkeys(BlockKind, 0)
        for entry in loops:
            open_[entry.kind] += 1
        open_[loop.kind] += 1
        problem = nesting_problem(open_, self.nesting)
        if problem is not None:
            raise MintError(STACK_OVERFLOW, detail=problem)
        loops.append(loop)

    def frame_loops(self) -> int:
        """Where the running subroutine's or handler's loops start on the loop stack; those below are its callers'."""
        return self.frames[-1].loops if self.frames else 0

    def leave_loop(self, opener: int) -> None:
        """Drop the loop opened at ``opener`` and anything a GOTO left open inside it, in the running frame only."""
        loops = self.loops
        for depth in range(len(loops) - 1, self.frame_loops() - 1, -1):
            if loops[depth].opener == opener:
                del loops[depth:]
                return

    def _innermost(self) -> int | None:
        """Where the running frame's innermost loop is on the stack (IF blocks above it do not count)."""
        loops = self.loops
        for depth in range(len(loops) - 1, self.frame_loops() - 1, -1):
            if loops[depth].kind is not BlockKind.IF:
                return depth
        return None

    def innermost_loop(self, opener: int) -> Loop | None:
        """The running frame's innermost loop, if it is the one opened at ``opener``."""
        loops = self.loops
        if loops and loops[-1].opener == opener:  # the common case, every NEXT: no IF block left open above it
            frames = self.frames
            if not frames or len(loops) > frames[-1].loops:
                return loops[-1]
        depth = self._innermost()
        return self.loops[depth] if depth is not None and self.loops[depth].opener == opener else None

    def exit_loop(self) -> Loop | None:
        """Leave the running frame's innermost loop for ``EXIT``, and the IF blocks inside it; None when none."""
        depth = self._innermost()
        if depth is None:
            return None
        loop = self.loops[depth]
        del self.loops[depth:]
        return loop

    # ------------------------------------------------------------------ errors

    def fail(self, error: MintError, pc: int) -> None:
        """A run-time error at ``pc``: record it, then call ``#ONERROR`` or end the run."""
        site = self.sites[pc] if pc < len(self.sites) else None
        try:
            number = self.occurred(error, pc)
        except NotSimulated as missing:
            self.pc = pc
            self.not_simulated(missing)
            return
        if number is None:  # an error no handler may take
            self.pc = pc
            self.halt(error, site)
            return
        handler = self.events.error_handler() if self.events is not None else None
        inside_handler = any(frame.rank == 0 for frame in self.frames)
        if handler is not None and not inside_handler:
            self._call_onerror(handler, error, pc)
            return
        self.pc = pc
        self.halt(error, site)

    def occurred(self, error: MintError, pc: int) -> int | None:
        """Set ``ERR``, ``ERL`` and ``ERRAXIS`` for ``error`` at ``pc``: they name the last error that occurred
        (000:9884-9886, 9904, 9923), from the moment it does, before ``#ONERROR`` runs. Returns the error's
        number, None for one no handler may take (nothing is set); raises ``NotSimulated`` for an error the
        dialect does not number here."""
        number = self.errors.number(error)
        if number is not None:
            site = self.sites[pc] if pc < len(self.sites) else None
            self.record_error(number, site.line if site else 0, error.axis)
        return number

    def _call_onerror(self, handler: int, error: MintError, pc: int) -> None:
        """Call ``#ONERROR`` for ``error`` at ``pc``: its RETURN resumes after the failing statement (EV-19 RC),
        or for an error the program cannot go on from, comes back to it and ends the run there. It is called
        even with the GOSUB stack full (the error may be that very stack overflowing, 000:4597-4598)."""
        if not self.errors.resumes(error):
            self._enter(handler, 0, pc, pc)
            self.frames[-1].ending = error.with_traceback(None)  # not the frames it was raised through
            return
        recovery = self.recoveries.get(pc)
        if recovery is not None and recovery.loop is not None:
            self.leave_loop(recovery.loop)
        self._enter(handler, 0, pc + 1 if recovery is None else recovery.resume, pc)

    def halt(self, error: MintError, site: Site | None) -> None:
        """End the run on an error no handler takes: the controller prints its message and aborts every axis
        (000:4579-4581, 4605-4609)."""
        if self.stopped is None:
            self.announce(self.error_message(error, site, explained=False))
        self.stop(StopReason.ERROR, self.error_message(error, site), site)
        self.on_fatal()

    def error_message(self, error: MintError, site: Site | None, *, explained: bool = True) -> str:
        """The message of ``error`` at ``site``, as the dialect words it."""
        if site is None:
            return self.errors.message(error, None, None, explained=explained)
        return self.errors.message(error, site.unit, site.line, explained=explained)

    def record_error(self, code: int, line: int, axis: int | None) -> None:
        self.err = float(code)
        self.erl = float(line)
        self.erraxis = float(axis) if axis is not None else -1.0
