"""An input given both a level at a time and a position to follow is refused at the second, as two positions are.

An input that follows an encoder is high exactly while the comparison holds (runtime/scenario/README.md,
the stimulus table), every tick: a level set at a time on the same input never showed, and the run went on
without a word, so a test of a limit switch forced on at 50 ms read the switch low.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from mintlang.runtime.scenario import ScenarioError, load_scenario, parse_directives
from mintlang.runtime.scenario.problems import ScenarioFileError
from tests.runtime.invoking import write

POSITION, LEVEL = "REM @sim input 4 when enc 0 >= 10", "REM @sim input 4 1 at 50"


def test_a_level_after_the_position_is_refused() -> None:
    _, problems = parse_directives(f"{POSITION}\n{LEVEL}\n")
    message = "input 4 follows a position (line 1): a level set at a time would never show"
    assert problems == [ScenarioError("program", 2, message, 5)]


def test_a_position_after_a_level_is_refused() -> None:
    _, problems = parse_directives(f"{LEVEL}\n{POSITION}\n")
    message = "input 4 is set at a time (line 1), so it cannot also follow a position"
    assert problems == [ScenarioError("program", 2, message, 5)]


def test_a_scenario_file_refuses_it_at_the_second_table(tmp_path: Path) -> None:
    path = write(
        tmp_path,
        "cell.scenario.toml",
        "[[input]]\nchannel = 4\nwhen = 'enc 0 >= 10'\n\n[[input]]\nchannel = 4\nlevel = 1\nat_ms = 50\n",
    )
    with pytest.raises(ScenarioFileError) as raised:
        load_scenario(path)
    assert [str(error) for error in raised.value.errors] == [
        f"{path}:5: input 4 follows a position (line 1): a level set at a time would never show"
    ]


def test_levels_at_times_on_another_input_are_kept() -> None:
    scenario, problems = parse_directives(f"{POSITION}\nREM @sim input 5 1 at 50\nREM @sim input 5 0 at 70\n")
    assert problems == []
    assert (len(scenario.position_inputs), len(scenario.inputs)) == (1, 2)
