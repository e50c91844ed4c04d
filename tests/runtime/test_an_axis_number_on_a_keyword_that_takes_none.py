"""mint-run refuses an axis or channel number on a keyword that takes none before the program starts.

``a = TIME.2`` and ``TIME.5`` are error 2003 "Syntax error" in mint check (the reasons, and why 2003, are in
tests/analysis/test_an_axis_number_on_a_keyword_that_takes_none.py). A syntax error is found when the
controller compiles the program, before it runs (000:4563-4568), and printed as a compile-time error,
``C`` rather than ``R`` (000:4584-4588).
"""

from __future__ import annotations

import pytest

from tests.runtime.running import assert_syntax_error_before_it_runs


@pytest.mark.parametrize("line", ["a = TIME.2", "TIME.5"])
def test_mint_run_stops_before_the_program_starts(line: str) -> None:
    # a compile error: nothing runs, so "before" is never printed, and the message names line 3
    assert_syntax_error_before_it_runs(line)
