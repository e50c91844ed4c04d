"""Scenarios: the scripted world of a run (stimulus) and what the run must show (expectations).

A scenario comes from ``REM @sim``/``REM @expect`` lines in the program
(``parse_directives``), from a TOML file (``load_scenario``), or both
(``merge``); the format is described in this package's README.
"""

from mintlang.runtime.scenario.directives import parse_directives
from mintlang.runtime.scenario.expectations import (
    STOP_REASONS,
    Comparison,
    Expectation,
    Observer,
    Origin,
    Outcome,
    StoppedExpectation,
    TerminalExpectation,
    ValueExpectation,
    all_held,
    evaluate,
    expectations_at,
    expectations_pass,
    render_outcomes,
    stop_fails,
)
from mintlang.runtime.scenario.files import load_scenario
from mintlang.runtime.scenario.problems import ScenarioError, ScenarioFileError
from mintlang.runtime.scenario.stimulus import (
    AdcLevel,
    DrivesEnabled,
    FastInput,
    HostPacket,
    IndexPulse,
    InputLevel,
    Keys,
    PlantChoice,
    PositionInput,
    Scenario,
    merge,
)

__all__ = [
    "STOP_REASONS",
    "AdcLevel",
    "Comparison",
    "DrivesEnabled",
    "Expectation",
    "FastInput",
    "HostPacket",
    "IndexPulse",
    "InputLevel",
    "Keys",
    "Observer",
    "Origin",
    "Outcome",
    "PlantChoice",
    "PositionInput",
    "Scenario",
    "ScenarioError",
    "ScenarioFileError",
    "StoppedExpectation",
    "TerminalExpectation",
    "ValueExpectation",
    "all_held",
    "evaluate",
    "expectations_at",
    "expectations_pass",
    "load_scenario",
    "merge",
    "parse_directives",
    "render_outcomes",
    "stop_fails",
]
