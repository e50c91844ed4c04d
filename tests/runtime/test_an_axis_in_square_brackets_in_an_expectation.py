"""An expectation names an axis in square brackets as a program does: ``IDLE[0]`` is ``IDLE.0``.

The v4 guide gives an axis keyword's axis after a dot or in square brackets (000:196-210, 556-557;
``PAUSE IDLE[0]``, 000:660-671), as the v3 guide does (001:649-667); a channel keyword takes the dot only
(000:560), and an array's index goes in round brackets, square ones being axes (000:1063-1066). An expectation
``IDLE[0]`` was refused as naming no keyword, variable or element.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from mintlang.cli import main
from mintlang.dialect import Dialect
from mintlang.runtime.scenario import parse_directives
from mintlang.runtime.scenario.problems import Invalid
from mintlang.runtime.scenario.targets import Target, target
from tests.runtime.invoking import write


@pytest.mark.parametrize("dialect", [Dialect.V4, Dialect.V3, Dialect.MINTMT])
@pytest.mark.parametrize(
    ("written", "canonical"),
    [("IDLE[0]", "IDLE.0"), ("pos[ 2 ]", "POS.2"), ("ID[1]", "IDLE.1")],  # any case, spacing or abbreviation
)
def test_one_axis_in_square_brackets_is_the_axis_after_a_dot(dialect: Dialect, written: str, canonical: str) -> None:
    assert target(written, dialect) == Target(canonical, every_axis=False)


@pytest.mark.parametrize(
    ("written", "message"),
    [
        ("IN[3]", "IN takes its channel after a dot, IN.3, not in brackets"),
        ("ADC[1]", "ADC takes its channel after a dot, ADC.1, not in brackets"),
        ("count[2]", "count[2]: an array's element is written count(2), in round brackets"),
        ("COMMS[5]", "COMMS has no axis or channel, so it takes no [5]: write COMMS(5)"),
        ("TIME[0]", "TIME has no axis or channel, so it takes no [0]"),
        (
            "IDLE[0,1]",  # read by a program, the two axes' values ANDed as one (000:673-674)
            "IDLE[0,1] reads its axes as one value: expect each axis on its own (IDLE.0, IDLE.1), "
            "or IDLE alone for every axis",
        ),
    ],
)
def test_square_brackets_that_give_no_one_axis_say_what_to_write(written: str, message: str) -> None:
    with pytest.raises(Invalid) as refused:
        target(written)
    assert str(refused.value) == message


def test_a_directive_is_told_at_the_word_in_brackets() -> None:
    _, problems = parse_directives("DIM a\nREM @expect IN[3] = 1\n")
    assert [(problem.line, problem.column, problem.message) for problem in problems] == [
        (2, 13, "IN takes its channel after a dot, IN.3, not in brackets")
    ]


def test_mint_test_checks_the_axis_in_brackets(tmp_path: Path) -> None:
    """Axis 1 jogs from the start and axis 0 never moves: at 50 ms axis 1 is not idle and axis 0 is."""
    program = write(
        tmp_path,
        "jog.mnt",
        "REM @sim drives enabled\nREM @expect IDLE[1] = 0 at 50\nREM @expect IDLE[0] = 1 at 50\n"
        "JOG.1 = 1000\nLOOP\nENDL\n",
    )
    result = CliRunner().invoke(main, ["test", "-j", "1", "--color", "never", "-v", str(program)])
    assert result.exit_code == 0, result.output
    assert "IDLE.1 at 50 ms: 0, as expected" in result.output


@pytest.mark.parametrize(
    ("written", "message"),
    [
        ("IDLE(0)", "IDLE(0): its axis goes after a dot or in square brackets, IDLE.0 or IDLE[0]; "),
        ("IN(3)", "IN(3): its channel goes after a dot, IN.3; "),  # it read the whole bank of inputs
        ("ADC(1)", "ADC(1): its channel goes after a dot, ADC.1; "),
    ],
)
def test_round_brackets_on_a_v4_axis_or_channel_say_what_to_write(written: str, message: str) -> None:
    """In v4 round brackets give an array's index, not an axis (000:1063-1066): ``mint check`` refuses ``IDLE(0)``."""
    with pytest.raises(Invalid) as refused:
        target(written)
    assert str(refused.value) == message + "round brackets give an array's index"


def test_round_brackets_still_give_an_element_of_comms_or_of_an_array() -> None:
    assert (target("COMMS(5)"), target("table(3)")) == (
        Target("COMMS(5)", every_axis=False),
        Target("TABLE(3)", every_axis=False, shown="table(3)"),
    )
