"""Ticks at which only the program can change: its slices run alone, 20 statements a tick as on every tick.

A program busy with variables (``runtime/interpreter/purity.py``) reads and
changes nothing outside the interpreter, so on ticks where the world, the
timer and the axes have nothing to do the simulator runs its slices without
the rest of the tick's work. Every expected time here is worked out from the
slice of 20 statements per 1 ms tick (RTM RC K = 20, ``runtime/BEHAVIOUR.md``),
and ``simulate`` checks that stepping every tick whole gives the same.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.runtime.interpreter.purity import is_pure
from mintlang.runtime.numbers import FUNCTIONS
from mintlang.runtime.run import run_source
from mintlang.runtime.simulation import Limits

from .running import simulate

COUNTING = "DIM i\nWHILE i < 1000\n  i = i + 1\nENDW\nPRINT TIME\n"


def test_a_loop_on_variables_keeps_twenty_statements_a_tick() -> None:
    # DIM and WHILE, then 1000 passes of two statements: PRINT is statement 2002 (from 0), in tick 2002 // 20
    assert simulate(COUNTING).terminal == "100\n"


def test_the_ticks_the_loop_runs_alone_are_not_processed_whole() -> None:
    processed: list[int] = []
    result = run_source(COUNTING, limits=Limits(), on_tick=lambda controller, tick: processed.append(tick))
    assert result.terminal == "100\n"
    assert processed == [0, 100]  # the first tick, and the one where PRINT reads TIME


def test_a_statement_failing_among_them_fails_on_its_own_tick() -> None:
    source = "DIM a\nDIM b\nWHILE 1\n  a = a + 1\n  IF a = 500 THEN b = 1 / 0\nENDW\n"
    # 3 statements before the loop, 3 a pass (a = a + 1, IF, ENDW): pass 500's division is statement
    # 3 + 3 * 499 + 2 = 1502, in tick 1502 // 20 = 75; 2021 is the division by zero, on line 5
    result = simulate(source)
    assert (result.stop.time_ms, result.err, result.erl) == (75, 2021.0, 5.0)


def test_the_timer_event_interrupts_the_loop_on_its_tick() -> None:
    source = (
        "DIM i\nDIM c\nTIMEREVENT = 10\nWHILE i < 1000\n  i = i + 1\nENDW\nPRINT c\nEND\n#TIMER\n  c = c + 1\nRETURN\n"
    )
    # 4 statements before the loop and 2000 in it put PRINT at 2004 of the program's own; each timer
    # event (every 10 ms from 10 ms) runs 2 more first: by tick 100, 10 events and 20 statements, so
    # PRINT is statement 2024 of the run, in tick 101, after the 10th event and before the 11th
    result = simulate(source)
    assert result.terminal == "10\n"
    assert result.stop.time_ms == 101


def test_a_debugger_that_shows_the_machine_at_each_statement_can_have_every_tick_processed_whole() -> None:
    processed: list[int] = []
    limits = Limits(program_alone=False)
    result = run_source(COUNTING, limits=limits, on_tick=lambda controller, tick: processed.append(tick))
    assert result.terminal == "100\n"
    assert processed == list(range(101))


def test_nested_for_loops_run_alone_with_twenty_statements_a_tick() -> None:
    source = "DIM i\nDIM j\nDIM s\nFOR i = 1 TO 10\n  FOR j = 1 TO 10\n    s = s + 1\n  NEXT\nNEXT\nPRINT TIME\n"
    # 3 DIMs and the outer FOR, then 10 passes of the inner FOR, 10 x (s = s + 1, NEXT) and the outer
    # NEXT (22 statements): PRINT is statement 224, in tick 224 // 20 = 11
    processed: list[int] = []
    result = run_source(source, limits=Limits(), on_tick=lambda controller, tick: processed.append(tick))
    assert result.terminal == "11\n"
    assert processed == [0, 11]  # the inner FOR, whose bounds read no loop variable, runs alone too
    assert simulate(source).terminal == "11\n"


@pytest.mark.parametrize(
    ("line", "alone"),
    [
        ("FOR i = 1 TO n STEP 2", True),
        ("FOR i = i + 1 TO 100", False),  # run again after a failure, it would start from another value
        ("FOR i = 1 TO a(i)", False),
        ("FOR i = 1 TO POS.0", False),  # a keyword: its tick is processed whole
        ("a = SQRT(b) * c(2) - 1", True),
        ("a = IN.3", False),
        ("IF a > 3 THEN b = 0", True),
        ("PRINT a", False),
        ("RETURN", False),  # ends an event handler too
        ("GOSUB sub", True),
    ],
)
def test_which_statements_may_run_alone(line: str, alone: bool) -> None:
    document = mintlang.parse(f"DIM a(5)\nDIM c(5)\n{line}\n#sub\nRETURN\n")
    statement = document.placed[2].syntax.statements[0]
    assert is_pure(statement, FUNCTIONS) is alone


def test_an_endw_whose_while_reads_time_waits_for_the_time_it_reads() -> None:
    # ENDW tests its WHILE's condition again: TIME there reads the tick each test runs in, so the loop ends in
    # tick 3, and ENDW runs alone only when its WHILE may (found by the metamorphic property)
    source = "WHILE TIME < 3 : ENDW\nPRINT TIME\n"
    processed: list[int] = []
    result = run_source(source, limits=Limits(), on_tick=lambda controller, tick: processed.append(tick))
    assert result.terminal == "3\n"
    assert processed == [0, 1, 2, 3]
    assert simulate(source).terminal == "3\n"
