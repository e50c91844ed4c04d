"""One simulated axis: parameters, move buffer, demand, plant, servo loop, errors.

The demand of an axis is a function of time between commands (its ``Move``),
so with the ideal plant the simulator can evaluate it at any tick without
stepping through the ones in between; an axis whose plant needs integration
(torque or velocity amplifier) or whose move is live asks for every tick, and
so does a stalled axis while its servo law still changes the DAC.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable

from mintlang.keyworddb.model import NEXTMOVES, Controller
from mintlang.records import record
from mintlang.runtime.clock import NEVER, Clock
from mintlang.runtime.errors import MintError
from mintlang.runtime.motion.moves import PROFILER_TICK_MS, Move, next_profiler_tick
from mintlang.runtime.motion.parameters import DEFAULTS, GAINS, SCALED, bounds, power_up
from mintlang.runtime.motion.plants import IdealPlant, Plant, round_half_away
from mintlang.runtime.motion.servo import ServoGains, ServoLoop
from mintlang.runtime.ranges import check_range

# AXISMODE bits (AX-1) and AXISERROR bits (AX-5)
MD_LINEAR, MD_JOG, MD_CIRCULAR, MD_TORQUE, MD_HOMING = 2, 4, 8, 16, 32
MD_OFFSET, MD_FOLLOW, MD_FLY, MD_CAM, MD_INCREMENT = 64, 128, 512, 1024, 16384
ER_ABORT, ER_FWD_HARD, ER_REV_HARD, ER_FWD_SOFT, ER_REV_SOFT, ER_FOLLOWING = 1, 2, 4, 8, 16, 32
ER_STOP_INPUT, ER_ERROR_INPUT = 64, 128
# the AXISSTATUS bits a condition of the last tick sets, and which clear with it (000:7275-7276); any other error
# latched (ABORT, a cam's synchronisation error) has no condition to watch and shows until cleared (000:6085)
CONDITIONS = ER_FWD_HARD | ER_REV_HARD | ER_FWD_SOFT | ER_REV_SOFT | ER_FOLLOWING | ER_STOP_INPUT | ER_ERROR_INPUT

POSITION_HALF_SPAN = float(1 << 23)  # the position counter wraps modulo 2^24 counts into [-2^23, 2^23) (MP-5 RC)
NOISE = 1e-6  # counts: closed-form set-points are exact only to ~1e-9 counts; limit tests ignore less than this
MOTION_IN_PROGRESS = 10
MOTION_ERROR = 12
DRIVE_NOT_ENABLED = 40
CONFIG_OFF = 0  # _cfOFF: the axis turned off, its encoder still read (000:8437, 8454-8455)
CONFIG_VIRTUAL = 5  # _cfVIRTUAL: moves without physical output, the position simulated (000:8442, 8456-8458)
DRIVE_ENABLED = 90  # _erDRIVE_ENABLED: what the drive must be disabled for, such as CONFIG (000:8481, 18821-18823)
DISABLED_AT_POWER_UP = "a drive starts disabled: enable it with DRIVEENABLE or RESET, or run with --drives enabled"
SERVO_TICK_S = 0.001
VEL_SAMPLE_S = (
    0.002  # VEL's sampling period: its least non-zero reading is one count in it, 500 counts/s (000:17120-17123)
)
GUARDS = frozenset(
    {
        "LIMITFORWARDINPUT",
        "LIMITREVERSEINPUT",
        "ERRORINPUT",
        "STOPINPUT",
        "SOFTLIMITFORWARD",
        "SOFTLIMITREVERSE",
        "SCALE",
    }
)


def wrap(counts: float) -> float:
    """A position in counts as the 24-bit position counter holds it (MP-5 RC)."""
    return (counts + POSITION_HALF_SPAN) % (2.0 * POSITION_HALF_SPAN) - POSITION_HALF_SPAN


@record(eq=False)
class Request:
    """A move waiting in the buffer; ``build`` makes it a ``Move`` at its start tick.

    Each load is its own move, told apart by identity: the same move loaded twice
    is two requests, and the buffers of a vector's axes must find this one.
    """

    mode: int
    axes: tuple[int, ...]
    build: Callable[[int], Move | None]  # start tick -> the move, or None when there is nothing to do
    targets: tuple[float, ...] | None = None  # each axis's end in counts, where known when it is loaded
    onto_running: bool = False  # starts on top of the move running (an OFFSET on a FOLLOW), not after it
    ident: float = 0.0  # MOVEBUFFERID in force when it was loaded (MintMT, MT-12)
    instant: bool = False  # acts when reached and moves nothing (a MintMT output move): the next starts with it


def _no_output(enabled: bool) -> None:
    """A drive with no enable output wired (a controller built without I/O)."""


def _no_error_output() -> None:
    """An axis error with no global error output wired (a controller built without I/O)."""


class Axis:
    def __init__(self, number: int, controller: Controller, clock: Clock, plant: Plant | None = None) -> None:
        self.number = number
        self.clock = clock
        self.parameters: dict[str, float] = dict(power_up(controller))
        self.bounds = {name: bounds(name, controller) for name in DEFAULTS}  # what each parameter accepts
        # MintDrive's axes, off at power-up (000:8421-8424), move, count and wait as its pages show: see turned_off
        self.off_runs_as_servo = controller not in NEXTMOVES
        self.plant: Plant = plant if plant is not None else IdealPlant()
        self._physical: Plant | None = None  # the motor's plant, set aside while the axis is virtual
        self.servo = ServoLoop()
        self.enabled = False  # drives start disabled (IO-7 RC)
        self.disabled_hint = DISABLED_AT_POWER_UP  # error 40's hint; a v3 controller's says how v3 switches it on
        self.drive_signal: Callable[[bool], None] = _no_output  # drives the DRIVEENABLEOUTPUT (drive_enable.py)
        self.error_signal: Callable[[], None] = _no_error_output  # drops GLOBALERROROUTPUT (global_error_output.py)
        self.axiserror = 0  # latched (AXISERROR)
        self.status = 0  # instantaneous conditions (AXISSTATUS)
        self.move: Move | None = None
        self.index_in_move = 0
        self.buffer: deque[Request] = deque()
        self.triggered = 0  # how many requests at the head of the buffer GO has triggered
        self.load_ident = 0.0  # MOVEBUFFERID written: stored with each move loaded from now on (MT-12)
        self.last_ident = 0.0  # the ident of the last move started: the running one's while it runs (MT-12)
        self.pending_mode = 0  # a mode bit shown from the moment it is issued (JOG, HOME, TORQUE, FOLLOW)
        self.hold = 0.0  # demand while no move runs, counts
        self.target = 0.0  # POSTARGET, counts
        self.jog_speed = 0.0  # JOG as last written, counts/s
        self.contour_mode = 0  # CONTOURMODE, stored with each path move as it is loaded (MP-32)
        self.contour_angle = 15.0  # CONTOURANGLE in degrees, read when segments join (MP-33)
        self.store_feedrate = False  # FEEDRATEMODE feedrate mode: each path move keeps the SPEED it was loaded at
        self.speed_override = 1.0  # FEEDRATEOVERRIDE / 100: scales SPEED for the moves that do not keep one
        self.position_offset = 0.0  # POS = (measured - offset) / SCALE
        self.encoder_offset = 0.0
        self.measured = 0
        self.previous_measured = 0
        self.earlier_measured = 0  # measured two servo ticks ago: VEL spans its 2 ms sample
        # ENCODERPRESCALE: a plant's own count (its encoder's edges) and, from the last change of the divider on,
        # the edge and the count it started from: the count the controller sees moves by one every divider edges
        self._edges = 0
        self._edges_origin = 0
        self._count_origin = 0
        self.demand = 0.0
        self.dac = 0.0
        self.torque: float | None = None  # TORQUE mode: the DAC command
        self.open_loop_dac: float | None = None  # DAC written by the program on an axis configured off
        self.guarded = False  # some limit, error or stop input, or a software limit, needs checking each tick
        self.held = False  # a stop input holds the axis (STOPINPUTMODE 1): its move stays, at rest, until released
        self.last_tick = 0
        # the demands of the two ticks before (the first None if it was processed) that a completed move still gave
        self.skipped_demands: tuple[float | None, float] | None = None
        self._setpoints: tuple[Move | None, int, float, int, float] = (None, -1, 0.0, -1, 0.0)
        self._last_demand = 0.0  # demand and demand velocity of the previous servo tick, for the feed-forwards
        self._last_velocity = 0.0

    # -------------------------------------------------------------- parameters

    @property
    def scale(self) -> float:
        return self.parameters["SCALE"]

    def get(self, name: str) -> float:
        value = self.parameters[name]
        return value / self.scale if name in SCALED else value

    def set(self, name: str, value: float) -> None:
        scale = self.scale if name in SCALED else 1.0
        check_range(name, value, self.bounds[name], self.number, scale)
        if name == "CONFIG" and value != CONFIG_OFF:
            self.open_loop_dac = None  # back to servo (or stepper) control: the loop drives the DAC again
        if name == "SCALE" and self.busy():
            raise MintError(MOTION_IN_PROGRESS, self.number, "SCALE can only change on an idle axis")
        if name == "ENCODERPRESCALE":
            self.count_from_here()
        self.parameters[name] = value * scale
        if name == "CONFIG":
            self.configured()
        if name in GUARDS:
            self.guarded = self._guarded()
        if name in GAINS:
            p = self.parameters
            self.servo.gains = ServoGains(
                kprop=p["KPROP"],
                kint=p["KINT"],
                kintlimit=p["KINTLIMIT"],
                kintmode=int(p["KINTMODE"]),
                kderiv=p["KDERIV"],
                kvel=p["KVEL"],
                kvelff=p["KVELFF"],
                kaccel=p["KACCEL"],
                daclimitmax=p["DACLIMITMAX"],
            )

    # ------------------------------------------------------------------ state

    def slew_speed(self) -> float:
        """The slew speed, counts/s, of a move this axis is master of and that keeps no feedrate of its own."""
        return self.parameters["SPEED"] * self.speed_override

    def loaded_feedrate(self) -> float | None:
        """The feedrate a path move loaded now keeps (FEEDRATEMODE's feedrate mode), counts/s; None in speed mode."""
        return self.parameters["SPEED"] if self.store_feedrate else None

    def busy(self) -> bool:
        return self.move is not None or bool(self.buffer) or bool(self.pending_mode)

    def position(self, counts: float) -> float:
        """POS of a physical count (measured, demand, target), in user units, as the wrapping counter reads it."""
        return wrap(counts - self.position_offset) / self.scale

    def absolute(self, counts: float) -> float:
        """The physical count at which the counter reads ``counts`` in the period the axis will be in when
        a move loaded now starts: an absolute move after a wrap moves by the difference from what POS reads."""
        reference = self.reference() - self.position_offset
        return counts + self.position_offset + reference - wrap(reference)

    @property
    def axisstatus(self) -> int:
        """AXISSTATUS: the conditions as they are now (AX-6), and the latched errors that have none."""
        return self.status | self.axiserror & ~CONDITIONS

    @property
    def axismode(self) -> int:
        move = self.move
        if move is None:  # a move GO has triggered shows from GO, as IDLE does (000:3033-3038)
            return self.pending_mode or (self.buffer[0].mode if self.triggered and self.buffer else 0)
        if self.triggered and self.buffer and self.buffer[0].onto_running:
            return move.mode | self.buffer[0].mode  # an OFFSET shows from GO, as on an idle axis
        return move.mode

    def demand_at(self, tick: int) -> float:
        """The servo demand at ``tick``: profiler set-points every 2 ms, linearly interpolated between (T-6)."""
        move = self.move
        if move is None:
            return self.hold
        if tick == self.last_tick:
            return self.demand  # already output: a move swapped in since then starts at the next profiler tick
        if tick % PROFILER_TICK_MS:
            # the set-point output at tick - 1 may belong to the move a command has just replaced
            before = self.demand if tick - 1 == self.last_tick else self._setpoint(move, tick - 1)
            return (before + self._setpoint(move, tick + 1)) / 2.0
        return self._setpoint(move, tick)

    def _setpoint(self, move: Move, tick: int) -> float:
        """A profiler set-point; the last two are remembered, as the servo ticks between them read them twice."""
        if move.live:
            return move.demand(self.index_in_move, tick)  # a live move may still change before that tick
        cache = self._setpoints
        if cache[0] is move:
            if cache[1] == tick:
                return cache[2]
            if cache[3] == tick:
                return cache[4]
        value = move.demand(self.index_in_move, tick)
        self._setpoints = (move, tick, value, cache[1], cache[2]) if cache[0] is move else (move, tick, value, -1, 0.0)
        return value

    def velocity_demand(self, tick: int) -> float:
        """Demand velocity in counts/s (its sign decides which limits apply, AX-14 RC)."""
        return self.move.velocity(self.index_in_move, tick) if self.move is not None else 0.0

    def configured(self) -> None:
        """CONFIG was written, or DEFAULT restored it: a virtual axis follows its demand on an ideal plant and drives
        no output (000:8456-8458), the motor's plant set aside; back from virtual, the motor is counted on from the
        simulated position, so POS and ENCODER do not jump."""
        virtual = self.parameters["CONFIG"] == CONFIG_VIRTUAL
        if virtual and self._physical is None:
            self._physical, self.plant = self.plant, IdealPlant(round_half_away(self.measured))
        elif not virtual and self._physical is not None:
            self.plant, self._physical = self._physical, None
            if isinstance(self.plant, IdealPlant):
                self.plant.position = round_half_away(self.measured)
            else:
                self.count_from_here()

    def turned_off(self) -> bool:
        """A NextMove axis configured off: its POS no longer counts and it is idle (000:15126-15127, 11750)."""
        return not self.off_runs_as_servo and self.parameters["CONFIG"] == CONFIG_OFF

    def idle(self) -> bool:
        """IDLE (AX-3): no move, none triggered, within IDLEPOS and IDLEVEL; a disabled or turned off axis is idle."""
        if not self.enabled or self.turned_off():
            return True
        if self.move is not None or self.pending_mode or self.triggered:
            return False
        p = self.parameters
        return abs(self.demand - self.measured) - NOISE <= p["IDLEPOS"] and abs(self.velocity_counts()) <= p["IDLEVEL"]

    def remaining(self) -> float:
        """POSREMAINING (MP-11), counts: what is left of the move in progress, not of the moves queued behind
        it; a move GO has triggered counts whole until it starts at the next profiler tick."""
        move = self.move
        if move is not None:
            if not move.buffered or move.end == NEVER:
                return 0.0
            return abs(move.demand(self.index_in_move, move.end) - self.demand)
        if self.triggered and self.buffer and (targets := self.buffer[0].targets) is not None:
            return abs(targets[self.buffer[0].axes.index(self.number)] - self.demand)
        return 0.0

    def count_from_here(self) -> None:
        """The divider is about to change (ENCODERPRESCALE, DEFAULT): what is counted stays, and the counts the
        controller sees go on from it at the new rate. An ideal plant's encoder reads the demand, in those counts."""
        self._edges_origin = self._edges
        self._count_origin = self.measured

    def velocity_counts(self) -> float:
        """VEL in counts/s: the change of the measured position over its sampling period (AX-4)."""
        return (self.measured - self.earlier_measured) / VEL_SAMPLE_S

    def _guarded(self) -> bool:
        p = self.parameters
        return (
            any(p[name] >= 0 for name in ("LIMITFORWARDINPUT", "LIMITREVERSEINPUT", "ERRORINPUT", "STOPINPUT"))
            or p["SOFTLIMITFORWARD"] != DEFAULTS["SOFTLIMITFORWARD"]
            or p["SOFTLIMITREVERSE"] != DEFAULTS["SOFTLIMITREVERSE"]
        )

    def dormant(self) -> bool:
        """Disabled, still and on a plant that cannot move by itself: a tick would change nothing.

        Its inputs and software limits still show in AXISSTATUS, so a guarded axis is never dormant.
        """
        return (
            not self.enabled
            and self.move is None
            and not self.buffer
            and not self.plant.closed_loop
            and self.measured == self.previous_measured == self.earlier_measured
            and not self.guarded
        )

    def watched_while_moving(self) -> bool:
        """A software limit or a following-error limit under half a count can trip between two events."""
        p = self.parameters
        return (
            p["SOFTLIMITFORWARD"] < DEFAULTS["SOFTLIMITFORWARD"]
            or p["SOFTLIMITREVERSE"] > DEFAULTS["SOFTLIMITREVERSE"]
            or p["FOLERRORFATAL"] < 0.5
        )

    def settling(self) -> bool:
        """The measured position changed on one of the last two ticks, so VEL and IDLE change on the next."""
        return self.measured != self.previous_measured or self.previous_measured != self.earlier_measured

    def next_event(self, now: int) -> int:
        """The next tick at which this axis changes in a way that matters beyond its demand value."""
        move = self.move
        if self.plant.closed_loop or (move is not None and (move.live or type(self.plant) is not IdealPlant)):
            return now + 1  # the demand leaves a stalled encoder behind: its following error grows every tick
        if move is not None:
            if self.held and now >= move.end:
                return NEVER  # at rest on a stop input: only the input clearing moves it on
            return now + 1 if self.watched_while_moving() else max(move.end, now + 1)
        if self.settling() or (type(self.plant) is not IdealPlant and not self._law_settled()):
            return now + 1
        if self.triggered and not self.held:
            return next_profiler_tick(now)
        return NEVER

    def _law_settled(self) -> bool:
        """At rest on a plant the law drives (not the ideal one), the DAC and the loop history stay as they are
        from the next tick on: always where the law is not in control, and on a stalled encoder once its
        derivative and integrator have done acting."""
        if not self.enabled or self.torque is not None or self.open_loop_dac is not None:
            return True
        hold = self.hold
        return (
            self._last_demand == hold
            and self._last_velocity == 0.0
            and self.servo.settled(hold, self.measured, self.dac)
        )

    def next_required(self, now: int) -> int:
        """The next tick the simulator must process for this axis's sake (readers use ``next_event``).

        A move that ends with nothing triggered behind it can be completed at any later tick (its
        end state is a function of time, and ``complete`` dates it back), and the settling ticks after
        it (VEL's 2 ms sample) only change what VEL and IDLE read: those ticks matter only to a program that reads the
        axis, whose reads ask for them. Limits, error and stop inputs need the exact tick.
        """
        move = self.move
        if type(self.plant) is not IdealPlant or self.guarded or (move is not None and move.live):
            return self.next_event(now)
        if move is None:
            return next_profiler_tick(now) if self.triggered and not self.held else NEVER
        if self.watched_while_moving():
            return now + 1
        if self.triggered and not self.held:
            return max(move.end, now + 1)
        return NEVER

    def complete(self, tick: int) -> None:
        """Finish a move whose end has passed: its end state, as if the tick it ended had been processed."""
        move = self.move
        if move is not None and tick >= move.end and not self.held and not move.live:
            if tick - 1 > self.last_tick:  # the servo skipped the ticks before, which the move still drove
                earlier = self.demand_at(tick - 2) if tick - 2 > self.last_tick else None
                self.skipped_demands = (earlier, self.demand_at(tick - 1))
            self.hold = move.demand(self.index_in_move, move.end)
            self.move = None
            if move.mode == self.pending_mode:
                self.pending_mode = 0

    # --------------------------------------------------------------- loading

    def require_ready(self) -> None:
        if self.axiserror:
            raise MintError(MOTION_ERROR, self.number, "clear the axis error with CANCEL or RESET first")
        if not self.enabled:
            raise MintError(DRIVE_NOT_ENABLED, self.number, self.disabled_hint)

    def stands_at(self, target: float) -> bool:
        """At rest on ``target`` with nothing loaded: a move there would go nowhere."""
        return self.move is None and not self.buffer and self.hold == target

    def buffer_free(self) -> int:
        """The free places of the move buffer: none, not fewer, once MOVEBUFFERSIZE is set below what it holds."""
        running = 1 if self.move is not None and self.move.buffered else 0
        return max(0, int(self.parameters["MOVEBUFFERSIZE"]) - len(self.buffer) - running)

    def reference(self) -> float:
        """Where a relative move starts from: the last loaded target, the end of a STOP's ramp
        (a move loaded behind it starts there), or the demand (MP-12 RC)."""
        if self.buffer or (self.move is not None and (self.move.buffered or self.move.end < NEVER)):
            return self.target
        return self.demand_at(next_profiler_tick(self.clock.now)) if self.move is not None else self.hold

    def go(self) -> None:
        """GO on a move that needs none (JOG, HOME, FOLLOW, TORQUE) is error 10 (000:11054-11056, 11117-11123)."""
        if self.move is not None and not self.move.buffered and not self.buffer and self.move.mode != MD_LINEAR:
            raise MintError(MOTION_IN_PROGRESS, self.number, "GO on an axis that is jogging, homing or following")
        if self.torque is not None:
            raise MintError(MOTION_IN_PROGRESS, self.number, "GO on an axis in torque mode")
        self.triggered = len(self.buffer)

    # ---------------------------------------------------------------- ticks

    def profiler(self, tick: int, start_group: Callable[[Request, int], None]) -> None:
        """A profiler tick: let a live move update, finish a completed move, start the next triggered one."""
        move = self.move
        if move is not None:
            if self.triggered and self.buffer and self.buffer[0].onto_running:
                self.triggered -= 1
                self.started(self.buffer.popleft()).build(tick)
            move.profiler(tick)
            if tick >= move.end and not self.held:
                self.hold = move.demand(self.index_in_move, move.end)
                self.move = None
                if move.mode == self.pending_mode:
                    self.pending_mode = 0
        while self.move is None and self.triggered and self.buffer and not self.held:
            head = self.buffer[0]
            start_group(head, tick)
            if not head.instant or (self.buffer and self.buffer[0] is head):
                break  # a move started, or the head waits for the other axes of its group

    def leaving(self) -> Move | Request | None:
        """The move a JOG or TORQUE written now would blend from: the one running, or else the one GO has
        triggered to start at the next profiler tick, which AXISMODE already shows (000:3033-3035)."""
        if self.move is not None:
            return self.move
        return self.buffer[0] if self.triggered and self.buffer else None

    def refuses_blend(self) -> bool:
        """JOG and TORQUE blend from any move but a homing cycle, a vector or a circle (000:3945-3948)."""
        move = self.leaving()
        if self.pending_mode == MD_HOMING:
            return True
        return move is not None and (move.mode in (MD_HOMING, MD_CIRCULAR) or len(move.axes) > 1)

    def started(self, request: Request) -> Request:
        """``request`` leaves the buffer to run: its ident is now the last one started."""
        self.last_ident = request.ident
        return request

    def begin(self, move: Move, index: int) -> None:
        self.move = move
        self.index_in_move = index

    def servo_tick(self, tick: int) -> None:
        """The servo loop at ``tick``: read the encoder, then compute the DAC for the next tick (SL-1).

        The law runs on every plant but the ideal one, whose encoder reads the demand whatever the DAC:
        there it would act on rounding alone, so the DAC reads 0. A stalled encoder does not answer the
        DAC either, but its following error is real, and the DAC shows the law pushing against it.
        """
        plant = self.plant
        servoing = self.enabled and self.torque is None
        counted = self.measured
        gap = tick - self.last_tick
        # after skipped ticks, the demands the encoder read on the two ticks before (None: the tick was processed)
        earlier: float | None = None
        before: float | None = None
        if gap > 1 and servoing and type(plant) is IdealPlant:
            # found before ``demand`` moves on: the demand of an odd tick is read from the one output before it
            if self.skipped_demands is not None:
                earlier, before = self.skipped_demands
            else:
                earlier = self.demand_at(tick - 2) if gap > 2 else None
                before = self.demand_at(tick - 1)
        self.skipped_demands = None
        demand = self.demand_at(tick)
        self.demand = demand
        if before is not None:
            self.earlier_measured = round_half_away(earlier) if earlier is not None else self.measured
            self.previous_measured = round_half_away(before)
        else:  # the tick before was processed, or the axis was at rest through the ticks skipped
            self.earlier_measured = self.previous_measured if gap == 1 else self.measured
            self.previous_measured = self.measured
        if type(plant) is IdealPlant:
            self.measured = plant.step(demand if servoing else None, 0.0, SERVO_TICK_S)
            self._unservoed_dac()
        else:
            self._edges = plant.step(demand if servoing else None, self.dac, SERVO_TICK_S)
            divider = self.parameters["ENCODERPRESCALE"]
            self.measured = self._count_origin + round_half_away((self._edges - self._edges_origin) / divider)
            consecutive = tick - self.last_tick == 1
            previous = self._last_demand if consecutive else self.demand_at(tick - 1)
            velocity = demand - previous
            acceleration = velocity - (self._last_velocity if consecutive else previous - self.demand_at(tick - 2))
            self._last_demand, self._last_velocity = demand, velocity
            if servoing and self.open_loop_dac is None:
                moved = self.measured - self.previous_measured
                self.dac = self.servo.step(demand, velocity, acceleration, self.measured, moved)
            else:
                self._unservoed_dac()
        if self.turned_off():
            self.position_offset += self.measured - counted
        self.last_tick = tick

    def _unservoed_dac(self) -> None:
        """The DAC while the law is not in control: as written on an axis configured off (SL-11), the
        TORQUE value (SL-9), or 0 on a disabled drive."""
        if self.open_loop_dac is not None:
            self.dac = self.open_loop_dac
        else:
            self.dac = self.torque if self.torque is not None and self.enabled else 0.0
        if self.torque is not None:
            self.track_measured()

    def track_measured(self) -> None:
        """In TORQUE mode the position loop is not in control: the demand follows the axis, so there is
        no following error and servoing resumes where the axis is when torque mode ends."""
        self.hold = self.demand = self._last_demand = float(self.measured)
        self._last_velocity = 0.0

    # ---------------------------------------------------------------- stopping

    def controlled_stop(self, tick: int, decel: float) -> Move | None:
        """Decelerate at ``decel`` from ``tick`` where the move allows it; the buffer is emptied (MP-22)."""
        self.buffer.clear()
        self.triggered = 0
        self.held = False
        move = self.move
        if move is None:
            self.pending_mode = 0
            return None
        stopped = move.stop(tick, decel) if decel > 0.0 else None  # a rate of 0 would never stop: at once
        if stopped is None:
            self.crash_stop()
            return None
        self.ramp_down(stopped)
        return stopped

    def ramp_down(self, stopped: Move) -> None:
        """Run ``stopped``, the ramp a controlled stop gives its move: where it ends is the target (MP-12)."""
        self.move = stopped
        self.target = stopped.demand(self.index_in_move, stopped.end) if stopped.end < NEVER else self.target

    def crash_stop(self) -> None:
        """Demand velocity to 0 at once; the demand stays where it is (MP-24 RC)."""
        if self.move is not None:
            self.hold = self.demand_at(self.clock.now)
        self.move = None
        self.buffer.clear()
        self.triggered = 0
        self.held = False
        self.pending_mode = 0
        if self.torque is not None:
            self.torque = None
            self.servo.reset()  # the loop restarts from the position reached, with no history
        self.target = self.hold

    def resync(self) -> None:
        """Demand := measured, so the following error is 0 (SL-10 RC) and AXISSTATUS stops showing one."""
        self.hold = float(self.measured)
        self.demand = self.hold
        self.target = self.hold
        self.status &= ~ER_FOLLOWING
        self.servo.reset()

    def latch(self, bit: int) -> None:
        self.axiserror |= bit
        self.error_signal()

    def enable(self) -> None:
        """Drive on. Where the servo law runs, it restarts from where the axis is, with no history (SL-10):
        a jammed axis enabled again does not push against the error it had before it was disabled."""
        if not self.enabled and type(self.plant) is not IdealPlant:
            self.resync()
        self.enabled = True
        self.drive_signal(True)

    def disable(self) -> None:
        """Drive off; a disabled axis has no following error, so AXISSTATUS stops showing one. A DAC written
        open loop stays as written, as on the ticks after (SL-11): ABORT, which disables every drive, does not
        stop motion controlled through DAC (000:6105)."""
        self.enabled = False
        self.drive_signal(False)
        self.dac = self.open_loop_dac if self.open_loop_dac is not None else 0.0
        self.status &= ~ER_FOLLOWING
