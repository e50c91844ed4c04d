"""A program that runs off its end stops at the last statement it ran, not at the last line of the file.

END ends the run where it is written (000:9841-9850). Without one, the run ends where the code runs
out, and the report names the statement that ran last: after a jump (GOTO, EXIT, a loop's last test)
that is the jump, wherever it sits. A MintMT ``Startup`` or ``Event`` block after the main code is
entered by the controller, never by the code around it (MT-7, mintlang/MINTMT.md; 004's restocking note
writes its main code, then its ``Event``, then its ``Startup``): stepping over it runs no statement, so
the end names the main code's last statement, not ``End Startup`` or ``End Event``.
"""

from __future__ import annotations

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import run_source
from mintlang.runtime.simulation import Limits

from .running import simulate

MAIN = 'Dim a\na = 1\nPrint "main"\n'


@pytest.mark.parametrize(
    ("source", "line", "statement"),
    [
        pytest.param(MAIN + '\nStartup\n  Print "startup"\nEnd Startup\n', 3, 'Print "main"', id="startup-after-main"),
        pytest.param(MAIN + "\nEvent TIMER\n  a = 2\nEnd Event\n", 3, 'Print "main"', id="event-after-main"),
        pytest.param(
            MAIN + "\nEvent TIMER\n  a = 2\nEnd Event\nStartup\n  a = 3\nEnd Startup\n",
            3,
            'Print "main"',
            id="event-then-startup-after-main",
        ),
        pytest.param('Startup\n  Print "startup"\nEnd Startup\nDim a\na = 1\n', 5, "a = 1", id="startup-before-main"),
        pytest.param(
            "Dim k\nLoop\n  k = k + 1\n  If k = 3 Then Exit\nEnd Loop\n\nEvent TIMER\n  k = 0\nEnd Event\n",
            4,
            "Exit",
            id="loop-left-by-exit-before-an-event",
        ),
    ],
)
def test_a_mintmt_program_ends_at_its_main_codes_last_statement(source: str, line: int, statement: str) -> None:
    result = run_source(source, dialect="mintmt", limits=Limits(until_ms=1_000, max_wall_s=60.0))
    assert (result.stop.reason, result.stop.line, result.stop.statement) == (StopReason.END, line, statement)


@pytest.mark.parametrize(
    ("source", "line", "statement"),
    [
        pytest.param("DIM a\na = 1\n", 2, "a = 1", id="last-line"),
        pytest.param("DIM a\na = 1\nEND\n", 3, "END", id="end"),
        pytest.param("DIM k\nGOTO done\nk = 2\n#done\n", 2, "GOTO done", id="goto-to-a-label-at-the-end"),
        pytest.param(
            "DIM k\nLOOP\n  k = k + 1\n  IF k = 50 THEN EXIT\nENDL\n", 4, "EXIT", id="exit-of-a-loop-at-the-end"
        ),
        pytest.param("DIM k\nDIM s\nFOR k = 1 TO 100\n  s = s + k\nNEXT\n", 5, "NEXT", id="for-loop-at-the-end"),
        pytest.param("DIM k\nWHILE k < 30\n  k = k + 1\nENDW\n", 4, "ENDW", id="while-loop-at-the-end"),
        pytest.param("DIM k\nIF k = 1 THEN k = 2\n", 2, "IF k = 1 THEN k = 2", id="if-then-not-taken-at-the-end"),
    ],
)
def test_a_v4_program_ends_at_the_statement_it_ran_last(source: str, line: int, statement: str) -> None:
    stop = simulate(source).stop
    assert (stop.reason, stop.line, stop.statement) == (StopReason.END, line, statement)
