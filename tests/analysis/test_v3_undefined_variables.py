"""Mint v3: a variable read before anything declares it is "Undefined Variables", in mint check as in mint-run.

v3 has no DIM for scalars: an assignment, FOR or INPUT declares a variable, at compile time and in
the order of the text, and a variable used before its declaration stops the compiler with
"Undefined Variables" (001:1352-1367, 1425-1429, 12971-12973). mint check reports it as E3001, the
v4 number of the same error, once per line at the first read; COMMSON declares the COMMS array
(001:13217-13247). Columns are counted by hand from 1.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import Limits, run_source
from tests.analysis.placed import placed_codes


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        pytest.param("a = b + 1\n", [("E3001", 1, 5)], id="read-never-assigned"),
        pytest.param("a = b + b * 2\n", [("E3001", 1, 5)], id="once-a-line"),
        pytest.param("PRINT total\ntotal = 5\n", [("E3001", 1, 7)], id="assigned-later-in-the-text"),
        pytest.param("IF flag THEN PRINT 1\n", [("E3001", 1, 4)], id="in-a-condition"),
    ],
)
def test_a_read_before_any_declaration_is_undefined_variables(
    source: str, expected: list[tuple[str, int, int]]
) -> None:
    assert placed_codes(source, dialect="v3") == expected


@pytest.mark.parametrize(
    "source",
    [
        pytest.param("b = 2\na = b + 1\nPRINT a\n", id="assignment-first"),
        pytest.param("FOR i = 1 TO 3\nPRINT i\nNEXT\n", id="for-declares"),
        pytest.param("INPUT n\nPRINT n\n", id="input-declares"),
    ],
)
def test_a_declared_variable_is_not_reported(source: str) -> None:
    assert "E3001" not in [code for code, _, _ in placed_codes(source, dialect="v3")]


def test_the_message_uses_the_v3_guides_name_and_says_what_declares() -> None:
    (diagnostic,) = mintlang.check("a = b + 1\n", dialect="v3")
    assert diagnostic.message.startswith("Undefined Variables: 'b' is read before anything declares it")


def test_mint_run_refuses_the_same_program_at_the_same_line_before_it_runs() -> None:
    source = "a = 1\nPRINT a, c\n"
    assert placed_codes(source, dialect="v3") == [("E3001", 2, 10)]
    run = run_source(source, dialect="v3", limits=Limits(until_ms=1000, max_wall_s=60.0))
    assert (run.stop.reason, run.terminal) == (StopReason.ERROR, "ERROR: Program: Undefined Variables at line 2\n")
