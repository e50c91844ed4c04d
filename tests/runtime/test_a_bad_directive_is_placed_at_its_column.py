"""A ``REM @expect`` or ``REM @sim`` line that cannot be read is reported at its line and column.

The column, from 1 as every other diagnostic of the project counts it (a misspelt ``@expext`` is placed
at its ``@``), is that of the word at fault, or just after the last word when one is missing; each was
counted by hand on the lines below. A value read whole but refused by what it builds (a command as the
target, a negative tolerance) is placed at that value too, not at the ``@``. A scenario file's ``when``
value is not placed: its words have no column of their own in the file.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from mintlang.runtime.hardware import machine
from mintlang.runtime.scenario import ScenarioError, load_scenario, parse_directives
from mintlang.runtime.scenario.problems import ScenarioFileError
from tests.runtime.test_mint_test import _mint_test
from tests.runtime.test_run_command import mint_run, write

NOT_A_COMPARISON = "expected a comparison (=, <>, >=, <=, >, <), not '~'"


@pytest.mark.parametrize(
    ("line", "column", "message"),
    [
        pytest.param("REM @expect x >< 3", 16, "expected a value to compare with as a number, not '<'", id="two-ops"),
        pytest.param("REM @expect x ~ 3", 15, NOT_A_COMPARISON, id="unknown-operator"),
        pytest.param("REM @expect x = ", 16, "expected a value to compare with at the end", id="no-value"),
        pytest.param("REM @expect x", 14, "expected a comparison at the end", id="no-comparison"),
        pytest.param("REM @expect", 12, "expected a keyword or variable at the end", id="nothing-expected"),
        pytest.param("REM @expect x => 3", 16, "expected a value to compare with as a number, not '>'", id="=>"),
        pytest.param("REM @expect x = 3 ± big", 21, "expected a tolerance as a number, not 'big'", id="tolerance"),
        pytest.param("REM @expect x = 3 at soon", 22, "expected a time in ms as a whole number, not 'soon'", id="at"),
        pytest.param("REM @expect x = 3 extra", 19, "unexpected 'extra' at the end", id="a-word-too-many"),
        pytest.param("GO.0 : REM @expect x ~ 3", 22, NOT_A_COMPARISON, id="after-GO"),
        pytest.param("REM @sim plant 0 velamp fast", 25, "expected the value of k as a number, not 'fast'", id="sim"),
        pytest.param("REM @sim plant 0 ideal 3", 24, "unexpected '3': give parameters as name=value", id="sim-extra"),
        pytest.param("REM @expect GO = 1", 13, "GO is a command, not a value to expect", id="target"),
        pytest.param("REM @expect x = 3 ± -1", 21, "a tolerance must be at least 0, not -1", id="negative-tolerance"),
        pytest.param("REM @expect x = 3 at -5", 22, "a time in ms must be at least 0, not -5", id="negative-time"),
        pytest.param(
            "REM @expect stopped bogus",
            21,
            "a run stops for one of end, error, until, deadlock, wall-limit, not 'bogus'",
            id="stop-reason",
        ),
        pytest.param('REM @expect terminal contains ""', 31, "the terminal text to look for is empty", id="empty-text"),
    ],
)
def test_the_column_is_that_of_the_word_at_fault(line: str, column: int, message: str) -> None:
    assert parse_directives(f"DIM x = 3\n{line}\n")[1] == [ScenarioError("program", 2, message, column)]


@pytest.mark.parametrize(
    ("line", "column", "message"),
    [
        pytest.param("REM @sim input 3 2 at 10", 18, "an input level is 0 or 1, not 2", id="level"),
        pytest.param(
            "REM @sim input 99 1 at 10", 16, "the NextMove BX has no input 99 (it has inputs 0 to 15)", id="input"
        ),
        pytest.param("REM @sim plant 9 ideal", 16, "the NextMove BX has no axis 9 (it has axes 0 to 7)", id="plant"),
        pytest.param(
            "REM @sim input 5 when enc 9 >= 5", 18, "the NextMove BX has no axis 9 (it has axes 0 to 7)", id="when"
        ),
        pytest.param(
            "REM @sim adc 0 150 at 10", 16, "an ADC level is a percentage from -100 to 100, not 150", id="percent"
        ),
        pytest.param(
            "REM @sim index 0 every 0", 24, "the counts between index pulses must be at least 1, not 0", id="every"
        ),
        pytest.param('REM @sim key "1" at -3', 21, "a time in ms must be at least 0, not -3", id="time"),
    ],
)
def test_a_sim_value_the_world_or_the_controller_refuses_is_placed_at_its_word(
    line: str, column: int, message: str
) -> None:
    """The NextMove BX has inputs 0 to 15 and axes 0 to 7 (runtime/scenario/README.md)."""
    _, problems = parse_directives(f"DIM x = 3\n{line}\n", controller=machine("nextmove-bx", "v4"))
    assert problems == [ScenarioError("program", 2, message, column)]


def test_mintmt_s_quote_comment_is_counted_the_same() -> None:
    _, problems = parse_directives("Dim x = 3\n' @expect x ~ 3\n", dialect="mintmt")
    assert [str(problem) for problem in problems] == [f"program:2:13: {NOT_A_COMPARISON}"]


def test_mint_run_and_mint_test_print_it_as_file_line_column(tmp_path: Path) -> None:
    program = write(tmp_path, "t.mnt", "DIM x = 3\nREM @expect x = \n")
    said = f"{program}:2:16: expected a value to compare with at the end"
    run = mint_run(program)
    assert (run.exit_code, run.stderr) == (2, f"mint-run: {said}\n")
    assert _mint_test(program, "--color", "never").stdout.splitlines()[0] == f"ERROR  {program}  {said}"


def test_mint_run_names_itself_on_each_line_of_several_problems(tmp_path: Path) -> None:
    # every mistake is reported at once (runtime/scenario/README.md), each a line of its own, as a compiler's are
    program = write(tmp_path, "t.mnt", "REM @sim input 3 2 at 10\nREM @expect x = \nDIM x\n")
    run = mint_run(program)
    assert run.exit_code == 2
    assert run.stderr == (
        f"mint-run: {program}:1:18: an input level is 0 or 1, not 2\n"
        f"mint-run: {program}:2:16: expected a value to compare with at the end\n"
    )


def test_a_scenario_file_s_when_is_placed_at_its_line_only(tmp_path: Path) -> None:
    scenario = write(tmp_path, "t.scenario.toml", '[[input]]\nchannel = 5\nwhen = "enc 0 => 500"\n')
    with pytest.raises(ScenarioFileError) as raised:
        load_scenario(scenario)
    assert [str(error) for error in raised.value.errors] == [
        f"{scenario}:3: expected a comparison (<=, >=, <, >), not '='"
    ]
