"""A RETURN in a MintMT Startup block has no GOSUB to return to: the controller runs the block at power-up
(004:128-133), not as a subroutine, so the RETURN is error 2010 (000:18965-18967) — in ``mint check``, as a RETURN
the main program reaches is, and when the line runs. In an Event block RETURN ends the handler, as ``End Event``
does (002:81-85, MT-7)."""

from __future__ import annotations

import mintlang
from mintlang.runtime.run import run_source

STARTUP = 'Print "main"\nStartup\n  Print "startup"\n  Return\nEnd Startup\n'


def _errors(source: str) -> list[tuple[str, int]]:
    analysis = mintlang.check_application(source, dialect="mintmt")
    return [(d.code, source.count("\n", 0, d.span.start) + 1) for d in analysis.program if d.code[0] == "E"]


def test_mint_check_reports_it_at_the_return() -> None:
    assert _errors(STARTUP) == [("E2010", 4)]


def test_the_run_stops_on_it_at_the_same_line() -> None:
    result = run_source(STARTUP, dialect="mintmt")
    assert (result.err, result.erl, result.terminal.splitlines()[0]) == (2010, 4, "startup")


def test_a_return_ending_an_event_block_early_is_fine() -> None:
    source = "Dim n\nLoop\n  n = n + 1\nEnd Loop\nEvent Comms1\n  If n > 0 Then Return\n  n = 0\nEnd Event\n"
    assert _errors(source) == []
