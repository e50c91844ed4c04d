"""Gathering the records of one source, and its mistakes, in the order written.

Both front ends build each record through a ``Collector``: a bad record
becomes a ``ScenarioError`` at its line and the rest are still read, and an
axis given two plants or two index pulses, an input given two position
switches (only one could decide its level) or two levels at one millisecond
(the inputs are polled once a servo tick, 000:11995: the first would never show), is
caught the same way in both.
"""

from __future__ import annotations

from collections.abc import Callable, Hashable

from mintlang.controllers import ControllerProfile
from mintlang.dialect import Dialect
from mintlang.runtime.comms import V3_READS_NO_HOST
from mintlang.runtime.scenario.expectations import Expectation
from mintlang.runtime.scenario.problems import Invalid, ScenarioError
from mintlang.runtime.scenario.reach import check_reach
from mintlang.runtime.scenario.stimulus import (
    HostPacket,
    IndexPulse,
    InputLevel,
    PlantChoice,
    PositionInput,
    Scenario,
    WorldRecord,
    scenario_of,
)


class Collector:
    """The records and errors of one source (a file path or ``"program"``)."""

    __slots__ = ("_driven", "_first", "controller", "dialect", "errors", "records", "source")

    def __init__(self, source: str, controller: ControllerProfile | None = None, dialect: Dialect = Dialect.V4) -> None:
        """With ``controller``, a record that drives an axis or channel it lacks is a mistake too; keywords
        are named in the program's ``dialect``."""
        self.source = source
        self.controller = controller
        self.dialect = dialect
        self.records: list[WorldRecord | Expectation] = []
        self.errors: list[ScenarioError] = []
        self._first: dict[tuple[type, Hashable], int] = {}  # (record kind, axis, channel, or channel and time) -> line
        self._driven: dict[int, tuple[type, int]] = {}  # input -> what first drives it (level or position), its line

    def error(self, line: int, message: str, *, column: int = 0) -> None:
        self.errors.append(ScenarioError(self.source, line, message, column))

    def add(
        self,
        line: int,
        build: Callable[[], WorldRecord | Expectation],
        line_of: Callable[[str], int] | None = None,
        *,
        column: int = 0,
        column_of: Callable[[str], int] | None = None,
    ) -> None:
        """Keep what ``build`` makes, or record why it could not: at the line of the key at fault when
        ``line_of`` finds it (a file's table), else at ``line``; at the column of the word at fault when
        the phrase reader knows it, or ``column_of`` (a directive's words) finds the word the value at fault
        came from, else at ``column`` (a directive's ``@``: the directive as a whole)."""
        try:
            record = build()
            if self.controller is not None:
                check_reach(record, self.controller)
            if self.dialect is Dialect.V3 and isinstance(record, HostPacket):
                raise Invalid(V3_READS_NO_HOST)
        except Invalid as problem:
            key = problem.key
            at_key = line_of(key) if line_of is not None and key is not None else None
            word = column_of(key) if column_of is not None and key is not None else 0
            self.error(problem.line or at_key or line, str(problem), column=problem.column or word or column)
            return
        once = _once(record)
        if once is not None:
            key, what, why = (type(record), once[0]), once[1], once[2]
            if key in self._first:
                self.error(line, f"{what} (line {self._first[key]}){why}", column=column)
                return
            self._first[key] = line
        if isinstance(record, InputLevel | PositionInput):
            kind, first = self._driven.setdefault(record.channel, (type(record), line))
            if kind is not type(record):
                self.error(line, _driven_both_ways(record, first), column=column)
                return
        self.records.append(record)

    def result(self) -> tuple[Scenario, list[ScenarioError]]:
        return scenario_of(self.records), self.errors


def _driven_both_ways(record: InputLevel | PositionInput, first: int) -> str:
    """What an input given a level at a time and a position to follow is told: the position decides its level
    every tick, so the levels would never show."""
    if isinstance(record, InputLevel):
        return f"input {record.channel} follows a position (line {first}): a level set at a time would never show"
    return f"input {record.channel} is set at a time (line {first}), so it cannot also follow a position"


def _once(record: WorldRecord | Expectation) -> tuple[Hashable, str, str] | None:
    """For a record that may be given once per axis, channel, or channel and time: that key, and what a second
    one is told, before and after the line of the first."""
    if isinstance(record, PlantChoice):
        return record.axis, f"axis {record.axis} already has a plant", ""
    if isinstance(record, IndexPulse):
        return record.axis, f"axis {record.axis} already has an index pulse", ""
    if isinstance(record, PositionInput):
        return record.channel, f"input {record.channel} already follows a position", ""
    if isinstance(record, InputLevel):
        why = ": inputs are read once a servo tick, so the first of the two levels would never show"
        return (record.channel, record.time_ms), f"input {record.channel} is already set at {record.time_ms} ms", why
    return None
