"""The statements after a one-line IF's THEN are stepped, and stopped at, at their own columns.

README.md, "Debugging": a line of several statements is stepped a statement at a time, each shown at
its column. The statements that follow THEN (000:1434, ``IF condition THEN statement``) are statements
of their own, but they were shown at column 1: their column was looked for after the end of the IF's
text, which holds them.

Columns counted by hand in ``  IF n = 0 THEN IF n < 1 THEN n = 2 : n = 3``: the outer IF at 3, the
inner IF at 17, ``n = 2`` at 31 and ``n = 3`` at 39.
"""

from __future__ import annotations

from tests.debugger.client import DapClient
from tests.debugger.conftest import Debug

NESTED = "DIM n\n  IF n = 0 THEN IF n < 1 THEN n = 2 : n = 3\nPRINT n\n"


def _where(client: DapClient) -> tuple[int, int]:
    frame = client.frames()[0]
    return frame["line"], frame["column"]


def test_each_statement_after_then_is_stepped_at_its_column(debug: Debug) -> None:
    client = debug(NESTED, breakpoints=(2,))
    client.stopped()
    seen = [_where(client)]
    for _ in range(3):
        client.step("next")
        seen.append(_where(client))
    assert seen == [(2, 3), (2, 17), (2, 31), (2, 39)]


def test_an_error_after_then_stops_at_the_statement_that_failed(debug: Debug) -> None:
    # index 4 of an array of 3 is error 2016 when the line runs (a variable index: 000:1063-1064)
    client = debug("DIM a(3)\nDIM n = 4\n  IF n = 4 THEN a(n) = 2\n")
    assert client.stopped()["reason"] == "exception"
    assert _where(client) == (3, 17)
