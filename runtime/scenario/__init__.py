"""Scenarios: the scripted world of a run (stimulus) and what the run must show (expectations).

A scenario comes from ``REM @sim``/``REM @expect`` lines in the program
(``parse_directives``), from a TOML file (``load_scenario``), or both
(``merge``); the format is described in this package's README.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from mintlang.lazy import import_when_used

if TYPE_CHECKING:
    from mintlang.runtime.scenario.directives import ignored_directives, parse_directives
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
        stop_fails,
    )
    from mintlang.runtime.scenario.files import load_scenario
    from mintlang.runtime.scenario.outcome_table import render_outcomes
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
    "ignored_directives",
    "load_scenario",
    "merge",
    "parse_directives",
    "render_outcomes",
    "stop_fails",
]

# Imported when first used: ``mint-migrate`` without ``--verify`` reads no scenario, and a run that checks no
# expectation does not render them (rich).
import_when_used(
    __name__,
    {
        **dict.fromkeys(["ignored_directives", "parse_directives"], "mintlang.runtime.scenario.directives"),
        **dict.fromkeys(
            [
                "STOP_REASONS",
                "Comparison",
                "Expectation",
                "Observer",
                "Origin",
                "Outcome",
                "StoppedExpectation",
                "TerminalExpectation",
                "ValueExpectation",
                "all_held",
                "evaluate",
                "expectations_at",
                "expectations_pass",
                "stop_fails",
            ],
            "mintlang.runtime.scenario.expectations",
        ),
        "load_scenario": "mintlang.runtime.scenario.files",
        "render_outcomes": "mintlang.runtime.scenario.outcome_table",
        **dict.fromkeys(["ScenarioError", "ScenarioFileError"], "mintlang.runtime.scenario.problems"),
        **dict.fromkeys(
            [
                "AdcLevel",
                "DrivesEnabled",
                "FastInput",
                "HostPacket",
                "IndexPulse",
                "InputLevel",
                "Keys",
                "PlantChoice",
                "PositionInput",
                "Scenario",
                "merge",
            ],
            "mintlang.runtime.scenario.stimulus",
        ),
    },
)
