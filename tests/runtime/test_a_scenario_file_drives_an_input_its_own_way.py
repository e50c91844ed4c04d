"""A scenario file laid over a program drives an input its own way, as its plant of an axis wins.

An input is driven by levels at times or by a position to follow (runtime/scenario/README.md, the stimulus
table). The program's ``REM @sim input 4 when enc 0 >= 10`` and a file's level for input 4 at 50 ms were both
kept, and the position decided the input every tick: the file's level never showed, without a word.
"""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from mintlang.cli import main
from mintlang.runtime.scenario import merge, parse_directives
from mintlang.runtime.scenario.stimulus import InputLevel, PositionInput, Scenario
from tests.runtime.invoking import write

SWITCH = PositionInput(channel=4, axis=0, operator=">=", counts=10)


def _program(text: str) -> Scenario:
    scenario, problems = parse_directives(text)
    assert problems == []
    return scenario


def test_a_level_in_the_file_replaces_the_program_s_position() -> None:
    merged = merge(_program("REM @sim input 4 when enc 0 >= 10\n"), Scenario(inputs=(InputLevel(50, 4, 1),)))
    assert (merged.inputs, merged.position_inputs) == ((InputLevel(50, 4, 1),), ())


def test_a_position_in_the_file_replaces_the_program_s_levels() -> None:
    program = _program("REM @sim input 4 1 at 50\nREM @sim input 5 1 at 60\n")
    merged = merge(program, Scenario(position_inputs=(SWITCH,)))
    assert (merged.inputs, merged.position_inputs) == ((InputLevel(60, 5, 1),), (SWITCH,))


def test_a_position_in_the_file_replaces_the_program_s_position() -> None:
    merged = merge(_program("REM @sim input 4 when enc 0 < 99\n"), Scenario(position_inputs=(SWITCH,)))
    assert merged.position_inputs == (SWITCH,)


def test_levels_at_times_in_both_are_kept_the_file_s_after_at_the_same_millisecond() -> None:
    program = _program("REM @sim input 4 1 at 50\nREM @sim input 4 0 at 90\n")
    merged = merge(program, Scenario(inputs=(InputLevel(50, 4, 0), InputLevel(70, 4, 1))))
    assert merged.inputs == (InputLevel(50, 4, 1), InputLevel(50, 4, 0), InputLevel(70, 4, 1), InputLevel(90, 4, 0))


def test_mint_test_reads_the_level_the_file_sets(tmp_path: Path) -> None:
    """Axis 0 never moves, so the program's switch alone would leave input 4 low; the file sets it at 50 ms."""
    write(
        tmp_path,
        "cell.mnt",
        "REM @sim input 4 when enc 0 >= 10\nREM @expect IN.4 = 0 at 40\nREM @expect IN.4 = 1 at 60\nLOOP\nENDL\n",
    )
    write(tmp_path, "cell.scenario.toml", "[[input]]\nchannel = 4\nlevel = 1\nat_ms = 50\n")
    result = CliRunner().invoke(main, ["test", "-j", "1", "--color", "never", str(tmp_path)])
    assert result.exit_code == 0, result.output
