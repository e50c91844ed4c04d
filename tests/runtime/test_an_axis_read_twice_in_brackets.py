"""The same axis named twice in the bracket notation is error 2018 (000:19053-19055), read as well as written:
``mint check`` reports ``POS[0,0]`` so, and the run stops on it when the line runs rather than reading axis 0
twice."""

from __future__ import annotations

import pytest

import mintlang
from mintlang.runtime.run import run_source
from tests.runtime.running import simulate


@pytest.mark.parametrize("line", ["PRINT POS[0,0]", "PAUSE IDLE[1,0,1]", "a = MOVEBUFFERFREE[2,2]"])
def test_a_constant_axis_read_twice_is_2018_in_check_and_run(line: str) -> None:
    source = f"DIM a\n{line}\n"
    errors = [d.code for d in mintlang.check_application(source, controller="nextmove-bx").program if d.code[0] == "E"]
    assert errors == ["E2018"]
    result = simulate(source)
    assert (result.err, result.erl, result.stop.line) == (2018, 2, 2)


def test_an_axis_given_twice_by_a_variable_is_2018_when_the_line_runs() -> None:
    result = simulate("DIM a = 1\nPRINT VEL[1,a]\n")
    assert (result.err, result.erl, result.terminal) == (2018, 2, "R2018: PROGRAM Axis set more than once [line 2]\n")


def test_mintmt_round_brackets_read_so_too() -> None:
    result = run_source("Print IDLE(0,0)\n", dialect="mintmt")
    assert (result.err, result.erl) == (2018, 1)


def test_distinct_axes_are_read_and_anded() -> None:
    # a bracket list read ANDs the axes' values (000:658-665): both idle at rest
    assert simulate("PRINT IDLE[0,1]\n").terminal == "1\n"
