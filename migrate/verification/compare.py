"""Two recordings side by side: how far they can be compared, and every first difference up to there.

A run that ended for good (the program's end with the machine at rest, a
deadlock, an error) holds its last state, so it compares with the other for as
long as that one runs. A run cut short (``--until-ms``, the wall clock, a
keyword the simulator does not model) is known only up to its last sample, so
the comparison stops there. How each run ended is compared too: a run over for
good must be met by the other's end of the same kind (an error by an error,
whose messages differ by dialect, X-PRINT) within ``TIME_MS``, and an error by
one the migrated run meets on a line made from the same statement (``origins``):
a migration that fails on the next line has run the one the original failed on.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

from mintlang.migrate.verification import printed, signals, tolerance
from mintlang.migrate.verification.model import Divergence, Place, Stopped
from mintlang.migrate.verification.runs import Recording
from mintlang.records import record
from mintlang.runtime.interpreter.vm import StopReason

_ORDER = ("stop", "terminal", "OUT", "relay", "axis")  # which of two differences at one time is told first


def horizon(v3: Recording, v4: Recording) -> int:
    """The last millisecond both runs tell about: the longer run when both ended, else the shorter open one
    (-1 when a run was cut short in its first millisecond: nothing can be compared)."""
    open_ends = [run.known for run in (v3, v4) if not run.closed]
    return min(open_ends) if open_ends else max(v3.last, v4.last)


def stopped(run: Recording) -> Stopped:
    stop = run.stop
    assert stop is not None, "a recording is made by a run"
    line = Place(stop.unit, stop.line) if stop.unit is not None and stop.line is not None else None
    return Stopped(stop.reason.value, stop.time_ms, line, stop.message)


Origins = Callable[[], Mapping[Place, frozenset[int]]]
"""The lines of the original each line of the migration was made from (``runnable.origins``), worked out
only when two errors are to be told apart: a diff of the files, most runs end without one."""


def differences(v3: Recording, v4: Recording, origins: Origins) -> list[Divergence]:
    """Every channel's first difference up to the horizon, the earliest first."""
    until = horizon(v3, v4)
    return in_order(
        [*_stops(v3, v4, until, origins), *printed.differences(v3, v4, until), *signals.differences(v3, v4, until)]
    )


def in_order(found: list[Divergence]) -> list[Divergence]:
    """Differences the earliest first, and of two at one time the one told first."""
    return sorted(found, key=lambda found: (found.time_ms, _ORDER.index(found.what.split(" ")[0])))


def _stops(v3: Recording, v4: Recording, until: int, origins: Origins) -> list[Divergence]:
    """How the runs ended, against each other: a run over for good while the other went on more than
    ``TIME_MS`` past it, two that ended differently (an error against an end), two errors on different
    statements, or two errors far apart.

    The v4 program ending first is no difference by itself: v3's GO waits for the move ahead (V3-10), so
    its program runs on after v4's has ended, and what it does meanwhile shows in the other channels."""
    runs = (v3, v4)
    ends = sorted((_End(stopped(run), run is v4) for run in runs if run.closed), key=lambda end: end.time_ms)
    if len(ends) == 1:  # the other was still running at the horizon, or cut short
        end = ends[0]
        return [_divergence(runs, end.time_ms, timing_only=False)] if end.noticed(until) else []
    if len(ends) < 2:
        return []
    first, second = ends
    if first.stop.reason != second.stop.reason:
        time = first.time_ms if first.noticed(second.time_ms) else second.time_ms
        return [_divergence(runs, time, timing_only=False)]
    if first.stop.reason != StopReason.ERROR.value:
        return []
    if not _same_statement(stopped(v3).line, stopped(v4).line, origins):
        return [_divergence(runs, second.time_ms, timing_only=False)]
    if first.noticed(second.time_ms):
        return [_divergence(runs, first.time_ms, timing_only=True)]
    return []


def _same_statement(v3: Place | None, v4: Place | None, origins: Origins) -> bool:
    """Whether the v4 run stopped on a line made from the v3 line its run stopped on; a line unknown, or one
    the migrator added, may be: only two lines known apart are told apart."""
    if v3 is None or v4 is None:
        return True
    made_from = origins().get(v4)
    return made_from is None or (v3.unit == v4.unit and v3.line in made_from)


@record
class _End:
    """How a run ended, and whether it is the v4 run."""

    stop: Stopped
    migrated: bool

    @property
    def time_ms(self) -> int:
        return self.stop.time_ms

    def noticed(self, other_still_running_at: int) -> bool:
        """Whether this end is a difference when the other run went on until ``other_still_running_at``."""
        if self.migrated and self.stop.reason == StopReason.END.value:
            return False
        return other_still_running_at - self.time_ms > tolerance.TIME_MS


def _divergence(runs: tuple[Recording, Recording], time_ms: int, *, timing_only: bool) -> Divergence:
    """Each run as it is at ``time_ms``: stopped (how, where) or running on (at which line)."""
    sides = []
    for run in runs:
        end = stopped(run)
        if run.closed and end.time_ms <= time_ms:
            told = f"{end.reason} at {end.time_ms} ms" + (f": {end.message}" if end.message else "")
            sides.append((told, end.line))
        else:
            sides.append(("runs on", run.places[min(time_ms, run.last)] if run.last >= 0 else None))
    (v3, v3_line), (v4, v4_line) = sides
    return Divergence(time_ms, "stop", v3, v4, v3_line, v4_line, timing_only=timing_only)
