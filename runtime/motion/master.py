"""Master selection for FOLLOW, FLY and CAM: MASTERSOURCE, MASTERCHANNEL, MASTERDISTANCE (spec FG-1, FG-2).

A slave reads its master once per profiler tick. What it reads is the master's
state at the last servo tick (the encoder sample, or the demand), so the order
in which axes are profiled does not matter. Only changes of the master position
move the slave, so position offsets (``POS`` written on an idle master) cancel
out unless they change while the slave follows.

The settings belong to the slave axis; they live in ``Motion.master_settings``
by axis number, so that the three master-slave modules share them without
widening ``Axis``, and a snapshot of the controller holds them.
"""

from __future__ import annotations

from collections.abc import Callable

from mintlang.keyworddb.model import Controller
from mintlang.records import record
from mintlang.runtime.clock import NEVER
from mintlang.runtime.errors import OUT_OF_RANGE, MintError
from mintlang.runtime.keywords import KeywordTable, per_channel
from mintlang.runtime.motion.axis import CONFIG_OFF, Axis
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.motion.moves import PROFILER_TICK_MS
from mintlang.runtime.ranges import check_range, table_bounds, table_default

MS_POS, MS_ENCODER, MS_AUXENCODER, MS_SPEED, MS_DEMAND = 0, 1, 2, 3, 4
INVALID_MASTER_CHANNEL = 70
DEFAULT_MASTER_DISTANCE = 1000.0  # FG-2 RC: the DEFAULT table's value
MAX_DISTANCE = 8_388_607.0
AUXILIARY_SCALE = 1.0  # counts per user unit of an auxiliary encoder: AUXENCODERSCALE is not simulated


@record(frozen=False)
class MasterSettings:
    """What a slave axis follows; ``channel`` None means the default for the source (FG-1)."""

    source: int = MS_POS
    channel: int | None = None
    distance: float = DEFAULT_MASTER_DISTANCE  # master user units

    def channel_of(self, slave: int) -> int:
        if self.channel is not None:
            return self.channel
        return slave if self.source == MS_SPEED else 0


def settings(motion: Motion, axis: Axis) -> MasterSettings:
    chosen = motion.master_settings
    found = chosen.get(axis.number)
    if found is None:
        found = chosen[axis.number] = MasterSettings(source=power_up_source(motion.profile.controller))
    return found


def power_up_source(controller: Controller) -> int:
    """MASTERSOURCE at power-up and after DEFAULT, from its attributes table: _msPOS on NextMove, _msAUXENCODER
    on MintDrive and ServoNode 51 (000:13925-13929)."""
    found = table_default("MASTERSOURCE", controller)
    return MS_POS if found is None else int(found)


class Master:
    """The master position of one master-slave move, in master encoder counts, sampled each profiler tick."""

    __slots__ = ("axis", "position", "source")

    def __init__(self, axis: Axis, source: int) -> None:
        self.axis = axis
        self.source = MS_ENCODER if source == MS_POS and axis.parameters["CONFIG"] == CONFIG_OFF else source
        self.position = 0.0  # the virtual master of _msSPEED starts at 0 (FG-1 RC)

    def sample(self) -> float:
        """The master position now; called once per profiler tick (a virtual master advances here)."""
        axis = self.axis
        source = self.source
        if source == MS_POS:
            return axis.measured - axis.position_offset
        if source == MS_ENCODER:
            return axis.measured - axis.encoder_offset
        if source == MS_DEMAND:
            return axis.demand - axis.position_offset
        self.position += axis.parameters["SPEED"] * PROFILER_TICK_MS / 1000.0
        return self.position

    @property
    def name(self) -> str:
        return f"axis {self.axis.number}"

    def at_rest(self, now: int) -> bool:
        """Whether the master stands where it is until something besides the motion changes: its axis runs no
        move, has none triggered and needs no tick (the virtual master of _msSPEED always advances)."""
        if self.source not in (MS_POS, MS_ENCODER, MS_DEMAND):
            return False
        axis = self.axis
        return axis.move is None and not axis.triggered and not axis.pending_mode and axis.next_event(now) >= NEVER


class AuxiliaryMaster:
    """An auxiliary encoder as the master (_msAUXENCODER): it reads as the program last set it, since nothing
    turns it in the simulation, so a slave moves only when AUXENCODER is written while it follows."""

    __slots__ = ("channel", "read")

    def __init__(self, read: Callable[[int], float], channel: int) -> None:
        self.read = read
        self.channel = channel

    def sample(self) -> float:
        return self.read(self.channel)

    @property
    def name(self) -> str:
        return f"auxiliary encoder {self.channel}"

    def at_rest(self, now: int) -> bool:
        """Only the program turns it, by writing AUXENCODER."""
        return True


@record
class Link:
    """A slave's view of its master at load time: the sampler, and the unit conversions."""

    master: Master | AuxiliaryMaster
    slave_per_master: float  # slave counts per master count at ratio 1 (user units on both sides, FG-1)
    master_scale: float  # master counts per master user unit (MASTERDISTANCE is in master units, FG-2)

    def distance_counts(self, distance: float) -> float:
        return distance * self.master_scale


class SetPoints:
    """A live slave's profiler set-points: the servo interpolates between the last two and extrapolates beyond
    the latest, since the next one depends on a master sample not taken yet (T-6)."""

    __slots__ = ("last", "origin", "previous", "started")

    def __init__(self, origin: float) -> None:
        self.origin = origin
        self.started = False
        self.previous = (0, origin)
        self.last = (0, origin)

    def start(self, tick: int) -> None:
        self.started = True
        self.last = (tick - PROFILER_TICK_MS, self.origin)

    def record(self, tick: int, position: float) -> None:
        self.previous, self.last = self.last, (tick, position)

    @property
    def position(self) -> float:
        return self.last[1]

    def still(self) -> bool:
        """The last two set-points are equal: the demand stands until the next one differs."""
        return self.started and self.previous[1] == self.last[1]

    def at(self, tick: int, ended: bool) -> float:
        (t0, p0), (t1, p1) = self.previous, self.last
        if not self.started:
            return self.origin
        if tick <= t0:
            return p0
        if ended and tick >= t1:
            return p1
        return p0 + (p1 - p0) * (tick - t0) / (t1 - t0)

    def velocity(self, tick: int, ended: bool) -> float:
        """Counts/s over the last profiler period."""
        (t0, p0), (t1, p1) = self.previous, self.last
        return 0.0 if ended or not self.started else (p1 - p0) * 1000.0 / (t1 - t0)


class MasterDriven:
    """A live move a master drives (a cam, FLY and FOLLOW): its demand and velocity are its ``points``, read
    as the servo reads them, held at the last once the move has ``end``-ed."""

    __slots__ = ()
    link: Link
    points: SetPoints
    end: int

    def _sample_master(self, tick: int) -> tuple[float, bool]:
        """The master's position at this profiler tick, and whether it is the move's first (its set-points
        start there)."""
        master = self.link.master.sample()
        first = not self.points.started
        if first:
            self.points.start(tick)
        return master, first

    def demand(self, index: int, tick: int) -> float:
        return self.points.at(tick, self.end != NEVER)

    def velocity(self, index: int, tick: int) -> float:
        return self.points.velocity(tick, tick >= self.end)


def link(motion: Motion, slave: Axis) -> Link:
    """The master of ``slave`` as its settings say; error 70 if it would follow itself."""
    chosen = settings(motion, slave)
    channel = chosen.channel_of(slave.number)
    if chosen.source == MS_AUXENCODER:
        auxiliary = AuxiliaryMaster(motion.auxiliary_encoder, channel)
        auxiliary.sample()  # an encoder the controller lacks is error 4 when the move loads
        return Link(auxiliary, slave.scale / AUXILIARY_SCALE, AUXILIARY_SCALE)
    master = motion.axis(channel)
    if master is slave and chosen.source != MS_SPEED:
        raise MintError(INVALID_MASTER_CHANNEL, slave.number, "a slave cannot follow itself")
    return Link(Master(master, chosen.source), slave.scale / master.scale, master.scale)


def master_distance(motion: Motion, slave: Axis) -> float:
    """MASTERDISTANCE of ``slave`` in master counts (scaled by the master channel, FG-2)."""
    chosen = settings(motion, slave)
    if chosen.source == MS_AUXENCODER:
        return chosen.distance * AUXILIARY_SCALE
    return chosen.distance * motion.axis(chosen.channel_of(slave.number)).scale


def register(table: KeywordTable, motion: Motion) -> None:
    motion.on_default.append(lambda axis: motion.master_settings.pop(axis.number, None))
    # the controller's own ranges come first: MintDrive takes only sources 2 and 3 and distances 1 to 65535
    sources = table_bounds("MASTERSOURCE", table.controller)
    channels = table_bounds("MASTERCHANNEL", table.controller)  # MintDrive: 0 alone (000:13799-13803)
    distances = table_bounds("MASTERDISTANCE", table.controller)

    def write_source(channel: int | None, value: float) -> None:
        axis = motion.axis(channel)
        check_range("MASTERSOURCE", value, sources, axis.number)
        if value != int(value) or not MS_POS <= value <= MS_DEMAND:
            raise MintError(OUT_OF_RANGE, axis.number, f"MASTERSOURCE = {value:g}")
        chosen = settings(motion, axis)
        chosen.source = int(value)
        chosen.channel = None  # writing the source resets the channel (FG-1)

    def write_channel(channel: int | None, value: float) -> None:
        axis = motion.axis(channel)
        check_range("MASTERCHANNEL", value, channels, axis.number)
        motion.axis(int(value))
        settings(motion, axis).channel = int(value)

    def write_distance(channel: int | None, value: float) -> None:
        axis = motion.axis(channel)
        check_range("MASTERDISTANCE", value, distances, axis.number)
        if abs(value) > MAX_DISTANCE:
            raise MintError(OUT_OF_RANGE, axis.number, f"MASTERDISTANCE = {value:g}")
        settings(motion, axis).distance = value

    def source(channel: int | None) -> float:
        return float(settings(motion, motion.axis(channel)).source)

    def master_channel(channel: int | None) -> float:
        axis = motion.axis(channel)
        return float(settings(motion, axis).channel_of(axis.number))

    def distance(channel: int | None) -> float:
        return settings(motion, motion.axis(channel)).distance

    table.register("MASTERSOURCE", read=source, write=per_channel(write_source))
    table.register("MASTERCHANNEL", read=master_channel, write=per_channel(write_channel))
    table.register("MASTERDISTANCE", read=distance, write=per_channel(write_distance))
