"""A RETURN the main program reaches has no GOSUB to return to: error 2010 when it runs.

The guide: "The keyword RETURN has been found without a GOSUB having being executed. Check that your main
program is terminated correctly (i.e. with END)" (000:18965-18968); RETURN returns to the statement after
the calling GOSUB (000:15671-15690). Ending the main program with RETURN instead of END, or returning from
it on a condition, stops the program on #2010 there. A RETURN after END, or after the endless loop that
ends the manual's programs, never runs; a subroutine's RETURN, or one of a label only GOTO reaches from a
subroutine, is fine.
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.placed import placed_codes


@pytest.mark.parametrize(
    ("source", "line", "column"),
    [
        ("PRINT 1\nRETURN\n", 2, 1),
        ("DIM a\nIF a THEN RETURN\nEND\n", 2, 11),
        ("GOTO here\n#here\nRETURN\n", 3, 1),
        ("PRINT 1 : RETURN\n", 1, 11),
    ],
)
def test_a_return_the_main_program_reaches_is_2010(source: str, line: int, column: int) -> None:
    assert placed_codes(source) == [("E2010", line, column)]


def test_it_is_raised_when_the_line_runs_and_says_to_end_with_end() -> None:
    (diagnostic,) = mintlang.check("PRINT 1\nRETURN\n")
    assert diagnostic.severity is mintlang.Severity.ERROR
    assert diagnostic.at_run_time
    assert diagnostic.message.startswith("RETURN w/o GOSUB:")
    assert "END" in diagnostic.message


@pytest.mark.parametrize(
    "source",
    [
        "GOSUB label1\nEND\n#label1\nPRINT 1\nRETURN\n",  # the guide's RETURN example (000:15684-15688)
        "GOSUB label1\nEND\n#label1\nIF IN1 THEN RETURN\nPRINT 1\nRETURN\n",  # returning on a condition
        "GOSUB main\nEND\n#main\nLOOP\nPRINT 1\nENDL\nRETURN\n",  # the manual's program structure
    ],
)
def test_a_subroutines_return_is_fine(source: str) -> None:
    assert placed_codes(source) == []


@pytest.mark.parametrize(
    "source",
    [
        # a subroutine ends through a label after END: the RETURN there returns to its GOSUB
        "GOSUB s\nEND\n#back\nPRINT 1\nRETURN\n#s\nPRINT 2\nGOTO back\n",
        # a shared exit the error handler jumps to, after the main program's endless loop
        "LOOP\nPRINT 1\nENDL\n#common\nPRINT 2\nRETURN\n#ONERROR\nGOTO common\n",
    ],
)
def test_a_return_after_the_main_program_stopped_that_a_subroutine_jumps_to_is_fine(source: str) -> None:
    assert placed_codes(source) == []


def test_a_label_after_a_stop_that_the_main_program_jumps_to_is_still_the_main_program() -> None:
    assert placed_codes("DIM a\nIF a THEN GOTO tail\nEND\n#tail\nRETURN\n") == [("E2010", 5, 1)]
