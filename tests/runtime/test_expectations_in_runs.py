"""Expectations observe a run without changing it."""

from __future__ import annotations

from mintlang.runtime.run import run_source
from mintlang.runtime.scenario import parse_directives


def test_expecting_an_edge_input_or_a_key_mid_run_leaves_them_to_the_program() -> None:
    # reading IN clears an edge latch and INKEY takes a key (IO-1, PR-5): an expectation only looks
    source = """REM @sim input 2 1 at 10
REM @sim key "a" at 10
REM @expect IN.2 = 1 at 50 ms
REM @expect INKEY = 65 at 50 ms
INPUTMODE = 4
WAIT = 100
PRINT IN.2, " ", INKEY
"""
    assert not parse_directives(source)[1]
    result = run_source(source, controller="nextmove-bx")
    assert result.terminal == "1 65\n"
    assert all(outcome.held for outcome in result.outcomes)
