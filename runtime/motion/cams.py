"""Cam profiles: CAMTABLE, CAM, CAMINDEX, CAMSTART, CAMEND (spec FG-11..FG-14).

A cam table is a user array: its first element is the segment count, then
one slave value per segment; an optional master table gives each segment's
master distance (all relative), otherwise MASTERDISTANCE applies to each. The
cam reads the arrays themselves, so it sees them as they are when a segment
starts. Segment boundaries are exact: master travel beyond a boundary belongs
to the next segment, and the slave starts each segment exactly where the last
one ended.
"""

from __future__ import annotations

from collections.abc import Callable

from mintlang.records import record
from mintlang.runtime.clock import NEVER
from mintlang.runtime.errors import MintError, NotSimulated
from mintlang.runtime.keywords import ArrayArgument, KeywordTable, per_channel
from mintlang.runtime.motion.axis import MD_CAM, MOTION_IN_PROGRESS, Axis, Request
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.motion.master import Link, MasterDriven, SetPoints, link, master_distance
from mintlang.runtime.motion.moves import Move
from mintlang.runtime.ranges import check_range, table_bounds

ABSOLUTE, TRUE_ABSOLUTE, CONTINUOUS, NO_INTERPOLATION, TRIGGER, RETRIGGER = 1, 2, 4, 8, 16, 32
TABLE_ERROR = 13
ER_SLAVE_SYNC = 2048  # AXISERROR bit 11: asynchronous slave synchronisation error (FG-14)
MAX_SKIPPED = 5  # segments that may pass within one profiler tick (FG-14)


@record(frozen=False)
class CamSettings:
    """An axis's selected tables and cam keywords, as CAMTABLE and the program left them."""

    positions: list[float] | None = None
    masters: list[float] | None = None
    start: int = 1
    end: int | None = None  # None: the table's last segment, whatever it holds when the cam starts
    index: int = 0
    mode: int = 0

    def segments(self) -> int:
        """The segment count of the position table, checked against the arrays (error 13)."""
        positions = self.positions
        if positions is None:
            raise MintError(TABLE_ERROR, detail="no cam table: use CAMTABLE first")
        count = positions[0]
        if count != int(count) or not 1 <= count <= len(positions) - 1:
            raise MintError(TABLE_ERROR, detail=f"the table's first element {count:g} is not its segment count")
        if self.masters is not None and len(self.masters) < count:
            raise MintError(TABLE_ERROR, detail="the master table is shorter than the cam table")
        return int(count)

    def range(self) -> tuple[int, int]:
        """CAMSTART and CAMEND, checked against the table (error 13)."""
        count = self.segments()
        end = count if self.end is None else self.end
        if not 1 <= self.start <= end <= count:
            raise MintError(TABLE_ERROR, detail=f"segments {self.start} to {end} of a {count}-segment table")
        return self.start, end

    def last(self) -> int:
        """CAMEND as read: the table's segment count until the program sets it (0 while no table holds one)."""
        if self.end is not None:
            return self.end
        positions = self.positions
        count = positions[0] if positions else 0.0
        return int(count) if count == int(count) and 1 <= count < len(positions or ()) else 0


class CamMove(MasterDriven):
    """A live move that steps the slave through the table as the master advances (FG-12)."""

    __slots__ = (
        "axes",
        "axis",
        "base_master",
        "bits",
        "buffered",
        "cycle_base",
        "default_distance",
        "distance",
        "end",
        "fail",
        "first",
        "from_position",
        "last",
        "link",
        "live",
        "masters",
        "mode",
        "points",
        "positions",
        "segment",
        "settings",
        "stopping",
        "to_position",
    )

    def __init__(
        self, axis: Axis, settings: CamSettings, link: Link, default_distance: float, fail: Callable[[], None]
    ) -> None:
        self.mode = MD_CAM
        self.axes = (axis.number,)
        self.end = NEVER
        self.buffered = True
        self.live = True
        self.link = link
        self.axis = axis
        self.settings = settings
        self.bits = settings.mode
        self.positions = settings.positions or []
        self.masters = settings.masters
        self.default_distance = default_distance  # MASTERDISTANCE in master counts when the cam started
        self.fail = fail  # raises AXISERROR bit 11 (crash stop, drive disabled)
        self.points = SetPoints(axis.hold)
        self.first, self.last = settings.range()
        self.segment = 0
        self.base_master = 0.0
        self.from_position = axis.hold  # slave demand where the segment starts
        self.to_position = axis.hold
        self.distance = 0.0  # master counts of the segment
        self.cycle_base = axis.hold  # the zero of an absolute cam's cycle
        self.stopping = False

    def _enter(self, segment: int) -> bool:
        """Set up ``segment``; False (after raising the error) if its master distance is not positive."""
        scale = self.axis.scale
        value = self.positions[segment] * scale
        if self.masters is not None:
            distance = self.link.distance_counts(self.masters[segment - 1])
        else:
            distance = self.default_distance
        if distance <= 0.0:
            self.fail()
            return False
        self.segment = segment
        self.settings.index = segment
        self.distance = distance
        if not self.bits & ABSOLUTE:
            self.to_position = self.from_position + value
        elif self.bits & TRUE_ABSOLUTE:
            self.to_position = self.axis.absolute(value)
        else:
            self.to_position = self.cycle_base + value
        return True

    def _next(self) -> int | None:
        """The segment after the current one: the next in the range, the start of a new cycle, or None."""
        if self.segment < self.last:
            return self.segment + 1
        if not self.bits & CONTINUOUS or self.stopping:
            return None
        self.first, self.last = self.settings.range()  # CAMSTART/CAMEND changes apply from the next cycle
        self.cycle_base = self.from_position
        return self.first

    def profiler(self, tick: int) -> None:
        master, first = self._sample_master(tick)
        points = self.points
        if first:
            self.base_master = master
            if not self._enter(self.first):
                return
        passed = 0
        while self.end == NEVER:
            travel = master - self.base_master
            if travel < self.distance:
                x = max(travel, 0.0) / self.distance
                change = self.to_position - self.from_position
                position = self.to_position if self.bits & NO_INTERPOLATION else self.from_position + change * x
                points.record(tick, position)
                return
            self.base_master += self.distance
            self.from_position = self.to_position
            passed += 1
            following = self._next()
            if following is None:
                self.end = tick
            elif passed > MAX_SKIPPED + 1 or not self._enter(following):
                if passed > MAX_SKIPPED + 1:
                    self.fail()
                return
        points.record(tick, self.from_position)

    def waits_on_master(self, now: int) -> bool:
        """Its segments are steps of master travel: it moves only when the master does."""
        return self.end == NEVER and self.points.still() and self.link.master.at_rest(now)

    def stop(self, tick: int, decel: float) -> Move | None:
        """FG-13 RC: finish the current cycle at its end segment, then stop."""
        self.stopping = True
        return self

    def replan(self, tick: int, speed: float, accel: float, decel: float, sramp: float) -> Move:
        return self  # ACCEL, DECEL and SPEED are not used by a cam (FG-12)


def register(table: KeywordTable, motion: Motion) -> None:
    state = [CamSettings() for _ in motion.axes]
    modes = table_bounds("CAM", table.controller)  # every bit the entry documents, past its table's 15

    def camtable(arguments: tuple[ArrayArgument, ...]) -> bool:
        """CAMTABLE(axis, positions, masters | NULL): select the tables, reset CAMSTART/CAMEND/CAMINDEX (FG-11)."""
        if len(arguments) != 3:  # NULL stands for no master table (000:7957-7958)
            raise MintError(TABLE_ERROR, detail="CAMTABLE(axis, positions, masters or NULL)")
        number, positions, masters = arguments
        if isinstance(number, list):
            raise MintError(TABLE_ERROR, detail="the first argument of CAMTABLE is an axis")
        axis = motion.axis(int(number))
        if not isinstance(positions, list) or not (isinstance(masters, list) or masters == 0.0):
            raise MintError(TABLE_ERROR, detail="CAMTABLE needs array names (and NULL for no master table)")
        chosen = CamSettings(positions, masters if isinstance(masters, list) else None, mode=state[axis.number].mode)
        state[axis.number] = chosen
        return False

    def cam(channel: int | None, value: float) -> None:
        """CAM = mode: load a cam into the buffer of an idle axis; GO starts it (FG-12, FG-14)."""
        axis = motion.axis(channel)
        settings = state[axis.number]
        check_range("CAM", value, modes, axis.number)
        if int(value) & (TRIGGER | RETRIGGER):
            raise NotSimulated("CAM", "_cmTRIGGER/_cmRETRIGGER: the fast latch trigger")
        settings.range()
        axis.require_ready()
        if axis.busy():
            raise MintError(MOTION_IN_PROGRESS, axis.number, "a cam needs an idle axis")
        master = link(motion, axis)
        settings.mode = int(value)
        distance = master_distance(motion, axis)

        def build(tick: int) -> Move | None:
            move = CamMove(axis, settings, master, distance, lambda: motion.on_error(axis, ER_SLAVE_SYNC))
            move.profiler(tick)
            return None if axis.axiserror else move  # a first segment without master distance fails at once

        axis.buffer.append(Request(MD_CAM, (axis.number,), build, ident=axis.load_ident))
        axis.pending_mode = MD_CAM

    def segment_writer(end: bool) -> Callable[[int | None, float], None]:
        keyword = "CAMEND" if end else "CAMSTART"
        segments = table_bounds(keyword, table.controller)  # whole segment numbers (supplements.whole_only)

        def write(channel: int | None, value: float) -> None:
            axis = motion.axis(channel)
            check_range(keyword, value, segments, axis.number)
            if end:
                state[axis.number].end = int(value)
            else:
                state[axis.number].start = int(value)

        return write

    table.register("CAMTABLE", array_command=camtable)
    table.register("CAM", read=lambda ch: float(state[motion.axis(ch).number].mode), write=per_channel(cam))
    table.register("CAMINDEX", read=lambda ch: float(state[motion.axis(ch).number].index))
    table.register(
        "CAMSTART", read=lambda ch: float(state[motion.axis(ch).number].start), write=per_channel(segment_writer(False))
    )
    table.register(
        "CAMEND", read=lambda ch: float(state[motion.axis(ch).number].last()), write=per_channel(segment_writer(True))
    )
