"""Gathering the records of one source, and its mistakes, in the order written.

Both front ends build each record through a ``Collector``: a bad record
becomes a ``ScenarioError`` at its line and the rest are still read, and an
axis given two plants or two index pulses is caught the same way in both.
"""

from __future__ import annotations

from collections.abc import Callable

from mintlang.controllers import ControllerProfile
from mintlang.runtime.scenario.expectations import Expectation
from mintlang.runtime.scenario.problems import Invalid, ScenarioError
from mintlang.runtime.scenario.reach import check_reach
from mintlang.runtime.scenario.stimulus import IndexPulse, PlantChoice, Scenario, WorldRecord, scenario_of


class Collector:
    """The records and errors of one source (a file path or ``"program"``)."""

    __slots__ = ("_per_axis", "controller", "errors", "records", "source")

    def __init__(self, source: str, controller: ControllerProfile | None = None) -> None:
        """With ``controller``, a record that drives an axis or channel it lacks is a mistake too."""
        self.source = source
        self.controller = controller
        self.records: list[WorldRecord | Expectation] = []
        self.errors: list[ScenarioError] = []
        self._per_axis: dict[tuple[type, int], int] = {}  # (record kind, axis) -> line first given

    def error(self, line: int, message: str) -> None:
        self.errors.append(ScenarioError(self.source, line, message))

    def add(self, line: int, build: Callable[[], WorldRecord | Expectation]) -> None:
        """Keep what ``build`` makes, or record why it could not."""
        try:
            record = build()
            if self.controller is not None:
                check_reach(record, self.controller)
        except Invalid as problem:
            self.error(problem.line or line, str(problem))
            return
        if isinstance(record, PlantChoice | IndexPulse):
            key = (type(record), record.axis)
            if key in self._per_axis:
                what = "a plant" if isinstance(record, PlantChoice) else "an index pulse"
                self.error(line, f"axis {record.axis} already has {what} (line {self._per_axis[key]})")
                return
            self._per_axis[key] = line
        self.records.append(record)

    def result(self) -> tuple[Scenario, list[ScenarioError]]:
        return scenario_of(self.records), self.errors
