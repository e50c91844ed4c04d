"""A keyword given one value for several axes in its brackets, with no ';' after it (W122).

With several axes, the values go to the axes in order: ``SPEED = 10`` under ``AXES[0,1,2]`` sets
axis 0 only (000:630-634), and a ';' after the last value gives it to every axis left
(000:656-659; v3 the same, 001:1109-1113). So ``DRIVEENABLE[0,1,2] = 1`` enables axis 0 alone:
listing axes 1 and 2 and giving them nothing is a slip, told with the ';' as an unsafe fix (it
changes what the line does, to what the brackets suggest was meant). Two values or more for more axes
are the guide's own way of leaving the last ones out (``MOVEA[0,1,2] = 10,20``, 000:578-581).
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.dialect import Dialect
from tests.analysis.checking import apply


def _warnings(source: str, dialect: Dialect = Dialect.V4) -> list[mintlang.Diagnostic]:
    return [d for d in mintlang.check(source, dialect=dialect) if d.code == "W122"]


def test_one_value_for_three_listed_axes_is_told_the_semicolon() -> None:
    source = "DRIVEENABLE[0,1,2] = 1\n"
    (warning,) = _warnings(source)
    assert warning.span.start == len("DRIVEENABLE[0,1,2] = ")
    assert warning.message == (
        "Fewer values than axes listed: DRIVEENABLE[0,1,2] = 1 sets axis 0 only, and axes 1 and 2 keep theirs;"
        " a ';' after the value gives it to every axis listed"
    )
    (fix,) = warning.fixes
    assert not fix.safe
    assert apply(source, fix.edits) == "DRIVEENABLE[0,1,2] = 1;\n"


def test_one_value_for_two_axes_names_the_one_left() -> None:
    (warning,) = _warnings("MOVEBUFFERSIZE[0,1] = 5\n")
    assert "MOVEBUFFERSIZE[0,1] = 5 sets axis 0 only, and axis 1 keeps its own;" in warning.message


@pytest.mark.parametrize(
    "line",
    [
        "DRIVEENABLE[0,1,2] = 1;",  # the last value to every axis left (000:656-659)
        "SPEED[0,1,2] = 10, 20, 30",
        "MOVEA[0,1,2] = 10,20",  # the guide's own move on axes 0 and 1 only (000:578-581)
        "SPEED[0,1,2] = ,10",  # a skipped place: the author counts the axes (000:635-637)
        "SPEED.1 = 10",
        "SPEED = 10",  # the AXES list's first axis, as the guide writes it (000:630-634)
        "PRINT POS[0,1]",
        "VECTORA[0,1] = 100",  # one position of a vector: its own error 2001 (000:16958), not a missing ';'
    ],
)
def test_lines_that_give_each_listed_axis_what_is_meant_are_not_reported(line: str) -> None:
    assert _warnings(f"AXES[0,1,2]\n{line}\n") == []


def test_v3_gives_its_values_the_same_way() -> None:
    assert len(_warnings("SPEED[0,1] = 10\n", Dialect.V3)) == 1


def test_the_axes_of_a_macro_for_an_axis_list_are_named_by_number() -> None:
    # A macro for an axis list stands for the list where it is written (000:1486-1498, ``SF.g1 = 10;``):
    # the axes it gives are 0, 1 and 2, not three times the macro's name.
    (warning,) = _warnings("DEFINE allAxes = [0,1,2]\nDRIVEENABLE.allAxes = 1\n")
    assert "DRIVEENABLE.allAxes = 1 sets axis 0 only, and axes 1 and 2 keep theirs;" in warning.message
