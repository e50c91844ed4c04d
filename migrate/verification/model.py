"""What a verification finds: a verdict, the first divergence, and what it could not verify."""

from __future__ import annotations

from enum import StrEnum

from mintlang.migrate.model import ManualItem
from mintlang.records import record
from mintlang.semantic.units import Unit

DEFAULT_UNTIL_MS = 10_000  # simulated time each run of a verification lasts at most
DEFAULT_WALL_S = 60.0  # real time each run may take


@record
class Application:
    """A program and its configuration file (None without one), as a run is given them."""

    program: str
    configuration: str | None

    def text(self, unit: Unit) -> str | None:
        return self.program if unit is Unit.PROGRAM else self.configuration


@record
class Place:
    """A line of one of the two applications: ``program`` or ``configuration``, from 1."""

    unit: str
    line: int

    def __str__(self) -> str:
        return f"{self.unit} line {self.line}"


class Verdict(StrEnum):
    EQUIVALENT = "equivalent"  # the same behaviour over the whole comparison, within the tolerances
    TIMING = "timing"  # the same outputs in the same order, at times X-GO-TIMING flagged as expected to change
    EXPLAINED = "explained"  # differences only in values a rule says v4 computes otherwise (M-TRIG: ``expected``)
    DIVERGES = "diverges"  # the runs differ: the first difference is reported
    INCOMPLETE = "incomplete"  # no difference as far as the simulation could go, which is not the whole run


@record
class Divergence:
    """The first thing that differs, at ``time_ms``: ``what`` (``terminal``, ``OUT``, ``relay``, ``axis 0
    position``, ``axis 0 velocity``, ``stop``), each run's side of it, and the line each run was at."""

    time_ms: int
    what: str
    v3: str
    v4: str
    v3_line: Place | None
    v4_line: Place | None
    detail: str = ""  # where in it: "at character 12"
    timing_only: bool = False  # the same values in the same order: only when they happen differs
    explained_by: str | None = None  # the rule whose values differ by design (``explained``): no divergence
    what_if: str | None = None  # found by a what-if run of the migration (``explained``): its v4 side is that run's


@record
class Stopped:
    """How a run ended: ``end``, ``deadlock``, ``error``, ``until`` …, when, and where."""

    reason: str
    time_ms: int
    line: Place | None
    message: str


@record
class Verification:
    """``verify``'s answer for one application."""

    verdict: Verdict
    compared_ms: int  # the simulated milliseconds compared, from 0
    divergence: Divergence | None  # the first difference in time
    differences: tuple[Divergence, ...]  # the first difference of each thing that differs, earliest first
    v3_controller: str
    v4_controller: str
    v3_stop: Stopped
    v4_stop: Stopped
    not_verified: tuple[tuple[str, ManualItem], ...]  # (unit, item): every manual item and application note
    disabled: tuple[Place, ...]  # flagged lines v4 finds in error, made comments for the v4 run
    short: str | None = None  # why the comparison ends before the runs do (INCOMPLETE)
