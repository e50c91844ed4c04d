"""Two levels for one input at the same millisecond are refused at the second: the first would never show.

The inputs are polled every servo tick (000:11995), and the simulator's tick is a millisecond: of
``input 3 1 at 50`` and ``input 3 0 at 50`` the program read only the 0, and the run went on without a word.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from mintlang.runtime.scenario import ScenarioError, load_scenario, parse_directives
from mintlang.runtime.scenario.problems import ScenarioFileError
from mintlang.runtime.scenario.stimulus import InputLevel
from tests.runtime.invoking import write

WHY = "inputs are read once a servo tick, so the first of the two levels would never show"


def test_a_second_level_at_the_same_millisecond_is_refused_at_its_directive() -> None:
    _, problems = parse_directives("REM @sim input 3 1 at 50\nREM @sim input 3 0 at 50\n")
    assert problems == [ScenarioError("program", 2, f"input 3 is already set at 50 ms (line 1): {WHY}", 5)]


def test_a_scenario_file_refuses_it_at_the_second_table(tmp_path: Path) -> None:
    path = write(
        tmp_path,
        "cell.scenario.toml",
        "[[input]]\nchannel = 3\nlevel = 1\nat_ms = 50\n\n[[input]]\nchannel = 3\nlevel = 1\nat_ms = 50\n",
    )
    with pytest.raises(ScenarioFileError) as raised:
        load_scenario(path)
    assert [str(error) for error in raised.value.errors] == [
        f"{path}:6: input 3 is already set at 50 ms (line 1): {WHY}"
    ]


def test_levels_a_millisecond_apart_or_of_two_inputs_are_kept() -> None:
    scenario, problems = parse_directives(
        "REM @sim input 3 1 at 50\nREM @sim input 3 0 at 51\nREM @sim input 4 1 at 50\n"
    )
    assert problems == []
    assert scenario.inputs == (InputLevel(50, 3, 1), InputLevel(50, 4, 1), InputLevel(51, 3, 0))
