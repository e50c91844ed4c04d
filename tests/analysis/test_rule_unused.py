"""The unused rule (``mintlang/analysis/rules/unused.py``): the complete list of diagnostics each small
program gets, as (code, severity, line); line numbers in comments refer to the Mint v4 guide (000_*)."""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.checking import WARNING, found


def test_a_variable_declared_and_never_used_is_a_warning() -> None:
    assert found("DIM spare\nDIM used\nPRINT used\n") == [("W103", WARNING, 1)]


def test_a_subroutine_never_called_is_a_warning() -> None:
    assert found("GOSUB called\nEND\n#called\nRETURN\n#orphan\nRETURN\n") == [("W104", WARNING, 5)]


def test_a_macro_never_used_is_a_warning() -> None:
    assert found("DEFINE slowSpeed = 1000\nDEFINE fastSpeed = 5\nSPEED = fastSpeed\n") == [("W105", WARNING, 1)]


def test_a_routine_of_only_dims_never_called_keeps_variables_non_volatile() -> None:
    # line 958: "non-volatile variables can be set-up by assigning them in a subroutine, but never calling the routine"
    source = (
        "GOSUB init\nEND\n#non_volatile\nDIM my_var1\nREM kept\nDIM my_var2\n\nRETURN\n"
        "#init\nmy_var1 = my_var1 + my_var2\nRETURN\n"
    )
    assert found(source) == []
    assert found(source.replace("REM kept", "PRINT 1")) == [("W104", WARNING, 3)]


@pytest.mark.parametrize("broken", ["FOR a = b 10\nNEXT\n", "IF (a<b) PRINT a\n"])
def test_variables_named_in_a_statement_that_does_not_parse_are_not_called_unused(broken: str) -> None:
    codes = [code for code, _, _ in found("DIM a\nDIM b\n" + broken)]
    assert "W103" not in codes and len(codes) == 1


def test_event_handlers_are_never_unused() -> None:
    assert found("END\n#ONERROR\nRETURN\n#TIMER\nRETURN\n#IN1\nRETURN\n") == []


@pytest.mark.parametrize(
    ("label", "meant"),
    [pytest.param("COMMS01", "COMMS1", id="comms01"), pytest.param("in007", "IN7", id="in007")],
)
def test_a_handler_written_with_a_leading_zero_is_a_subroutine_never_called_naming_the_handler(
    label: str, meant: str
) -> None:
    # the handlers are #INx and #COMMS1 .. #COMMS5 (000:1888-1898): #COMMS01 is a plain label, called by nothing
    (diagnostic,) = mintlang.check(f"END\n#{label}\nRETURN\n")
    assert (diagnostic.code, diagnostic.message) == (
        "W104",
        f"subroutine #{label} is never called by GOSUB or GOTO: the event handler is #{meant}, with no leading zero",
    )


def test_a_v3_routine_that_assigns_its_variables_and_is_never_called_keeps_them_non_volatile() -> None:
    # the v3 guide's NONVOL1 listing (001:1430-1450): in v3 an assignment declares (001:1352), and the
    # routine is never called, which is what keeps the variables (001:1408)
    source = (
        "GOSUB init\nGOSUB main\nEND\n#non_volatile\n    my_var1 = 0\n    my_var2 = 0\nRETURN\n"
        "#init\nRETURN\n#main\nRETURN\n"
    )
    assert [d.code for d in mintlang.check(source, dialect="v3")] == []
    called = source.replace("    my_var2 = 0\n", "    my_var2 = 0\n    GOSUB init\n")
    assert [d.code for d in mintlang.check(called, dialect="v3")] == ["W104"]
