"""Expectations observe a run without changing it, and none goes unchecked."""

from __future__ import annotations

from mintlang.runtime.run import run_source
from mintlang.runtime.scenario import parse_directives
from mintlang.runtime.simulation import Limits


def test_expecting_an_edge_input_or_a_key_mid_run_leaves_them_to_the_program() -> None:
    # reading IN clears an edge latch and INKEY takes a key (IO-1, PR-5): an expectation only looks
    source = """REM @sim input 2 1 at 10
REM @sim key "a" at 10
REM @expect IN.2 = 1 at 50 ms
REM @expect INKEY = 65 at 50 ms
INPUTMODE = 4
INPUTPOSTRIGGER = 4
WAIT = 100
PRINT IN.2, " ", INKEY
"""
    assert not parse_directives(source)[1]
    result = run_source(source, controller="nextmove-bx")
    assert result.terminal == "1 65\n"
    assert all(outcome.held for outcome in result.outcomes)


def test_an_expectation_timed_after_the_run_stopped_fails_and_says_why() -> None:
    source = 'REM @expect terminal contains "late" at 1000\nREM @expect TIME >= 0 at 5\nWAIT = 30\nPRINT "early"\n'
    result = run_source(source, controller="nextmove-bx")
    late, early = sorted(result.outcomes, key=lambda outcome: outcome.expectation.at_ms or 0, reverse=True)
    assert early.held
    assert not late.held
    assert late.detail == "the run stopped at 30 ms, before this check"


def test_an_expectation_after_until_ms_is_not_reached_either() -> None:
    result = run_source("REM @expect POS.0 = 0 at 500\nLOOP\nENDL\n", limits=Limits(until_ms=10))
    (outcome,) = result.outcomes
    assert not outcome.held and "stopped at 10 ms" in outcome.detail


def test_a_program_that_does_not_compile_is_still_judged_by_its_expectations() -> None:
    expected = (
        'REM @expect stopped error\nREM @expect ERR = 2009\nREM @expect ERL = 6\nREM @expect terminal contains "x"\n'
    )
    result = run_source(expected + "DIM a\nFOR a = 1 TO 2\n")  # never closed: the compiler's 2009 on line 6
    assert [outcome.held for outcome in result.outcomes] == [True, True, True, False]
