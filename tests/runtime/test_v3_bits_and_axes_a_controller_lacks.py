"""In Mint v3 an input or output bit outside 0 to 7 is "Out of Range", and an axis past the three a
controller has is refused, in ``mint check`` as in the run.

``b = IN.a`` with ``a`` outside ``0 <= a <= 7`` gives an "Out of Range" error (001:8965), and so does
``OUT.a = 0`` (001:10592); out of range is a system error, ``ERR`` 0 in ``#ONERROR`` (001:4918-4925),
after which RETURN goes on with the next line (001:5532). A v3 controller has three axes at most
(001:972), numbered from 0 (001:974); the guide names no error for a fourth, and the run reports it as
"Invalid axis" (``ERR`` 4), the error of an axis it cannot use (001:13173). ``mint check`` numbers them
as v4 does: 3 and 2.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.diagnostics import Severity
from mintlang.runtime.run import run_source

HANDLER = 'PRINT "next"\nEND\n#ONERROR\nPRINT "ERR ", ERR\nRETURN\n'


@pytest.mark.parametrize(
    ("line", "code", "where", "err"),
    [
        pytest.param("OUT.9 = 1", "E0003", "9", 0, id="001:10592 output bit 9"),
        pytest.param("x = IN.8", "E0003", "8", 0, id="001:8965 input bit 8"),
        pytest.param("SPEED.3 = 10", "E0002", "3", 4, id="001:972 a fourth axis"),
        pytest.param("x = POS[0,5]", "E0002", "5", 4, id="001:972 in brackets"),
        # every axis listed counts, whether or not it is given a value or the keyword is a command
        pytest.param("SPEED[0,1,2,3] = 5", "E0002", "3", 4, id="001:990-998 an axis given no value"),
        pytest.param("GO[0,1,2,3]", "E0002", "3", 4, id="001:8460 GO[axes]"),
        pytest.param("STOP[0,1,2,3]", "E0002", "3", 4, id="001:11841 STOP[axes]"),
        pytest.param("RESET[0,1,2,3]", "E0002", "3", 4, id="001:11395 RESET[axes]"),
        pytest.param("AXES[0,1,2,3]", "E0002", "3", 4, id="001:5967 AXES[axis list]"),
        pytest.param("AXES[3]", "E0002", "3", 4, id="001:5967 AXES of one axis"),
    ],
)
def test_the_check_finds_what_the_run_reports(line: str, code: str, where: str, err: int) -> None:
    source = f"{line}\n"
    errors = [d for d in mintlang.check(source, dialect="v3") if d.severity is Severity.ERROR]  # the run's kind
    assert [(d.code, source[d.span.start : d.span.end]) for d in errors] == [(code, where)]
    assert run_source(f"{line}\n{HANDLER}", dialect="v3").terminal == f"ERR {err}\nnext\n"


def test_a_bit_in_a_variable_is_out_of_range_when_the_line_runs() -> None:
    # the guide's own form, OUT.a = 0 with a outside 0 to 7 (001:10589-10592); OUT keeps its value
    program = f"a = 8\nOUT.a = 1\nPRINT OUT\n{HANDLER}"
    assert run_source(program, dialect="v3").terminal == "ERR 0\n0\nnext\n"


@pytest.mark.parametrize("line", ["OUT.7 = 1", "x = IN.0", "SPEED.2 = 10", "x = POS[0,1,2]"])
def test_the_bits_and_axes_a_controller_has_are_no_error(line: str) -> None:
    assert mintlang.check(f"{line}\n", dialect="v3") == []


@pytest.mark.parametrize("line", ["AXES[0,1]", "GO[0,1]", "STOP[0,1]", "SPEED[0,1] = 5"])
def test_an_axis_past_those_of_a_smaller_controller_is_invalid_axis(line: str) -> None:
    # a SmartMove/1 has one axis (001:178): axis 1 is one it lacks, as axis 3 is on a three-axis one
    result = run_source(f"{line}\n{HANDLER}", dialect="v3", controller="smartmove-1")
    assert result.terminal == "ERR 4\nnext\n"
