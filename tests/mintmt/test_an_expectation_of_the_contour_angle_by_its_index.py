"""An expectation reads what a program can read (runtime/scenario/README.md, "what"): a MintMT program reads the
inter-vector angle as ``CONTOURPARAMETER(axis, 0)`` or the note's ``CONTOURPARAMETER.axis.0`` (004:223, 232; MT-11),
so ``' @expect`` and a scenario file read it so too. It is v4's CONTOURANGLE, 15 degrees until written (000:8527).
The axis comes first and the index after it, as in the program; without the index there is nothing to read, and
an output move (``MOVEOUT(axis, bank)``), which is only written (004:295), is no value to expect.
"""

from __future__ import annotations

import pytest

from mintlang.dialect import Dialect
from mintlang.runtime.run import run_source
from mintlang.runtime.scenario.problems import Invalid
from mintlang.runtime.scenario.targets import Target, target

PROGRAM = """CONTOURPARAMETER([0,1],0) = 10, 20;
' @expect CONTOURPARAMETER(0,0) = 10
' @expect CONTOURPARAMETER.1.0 = 20
' @expect CONTOURPARAMETER(2,0) = 15
"""


def test_the_program_s_expectations_read_the_angle_of_each_axis() -> None:
    outcomes = run_source(PROGRAM, dialect="mintmt").outcomes
    assert [(outcome.held, outcome.actual) for outcome in outcomes] == [(True, "10"), (True, "20"), (True, "15")]


@pytest.mark.parametrize("written", ["CONTOURPARAMETER(1,0)", "contourparameter.1.0", "CONTOURPARAMETER( 1 , 0 )"])
def test_the_axis_then_the_index_however_written(written: str) -> None:
    named = target(written, Dialect.MINTMT)
    assert named == Target("CONTOURPARAMETER.1(0)", every_axis=False, shown="CONTOURPARAMETER(1,0)")


@pytest.mark.parametrize(
    "written", ["CONTOURPARAMETER", "CONTOURPARAMETER(0)", "CONTOURPARAMETER.0", "CONTOURPARAMETER(0,1,0)"]
)
def test_without_one_axis_and_its_index_nothing_is_named(written: str) -> None:
    with pytest.raises(Invalid, match=r"CONTOURPARAMETER\(axis, index\)"):
        target(written, Dialect.MINTMT)


def test_an_output_move_is_only_written() -> None:
    with pytest.raises(Invalid, match="MOVEOUT is only written"):
        target("MOVEOUT(0,0)", Dialect.MINTMT)


def test_another_dot_after_a_keyword_that_takes_no_index_names_nothing() -> None:
    with pytest.raises(Invalid, match="is not a keyword, variable or array element"):
        target("POS.0.1", Dialect.MINTMT)
