"""Where each MintMT Event block's handler ends, as the compiled program gives it to the debugger.

An ``Event NAME`` block holds its handler up to its ``End Event``; the code
after it is the program's again (MT-7), and Event blocks never nest (MT-13).
The ends come from the block analysis, not from the text of the lines, so
spacing, case and statements sharing the closer's line do not matter.
"""

from __future__ import annotations

from collections.abc import Mapping

from mintlang.runtime.controller import Controller
from mintlang.runtime.run import run_source


def _ends(source: str) -> Mapping[int, int]:
    found: list[Mapping[int, int]] = []

    def keep(controller: Controller) -> None:
        found.append(controller.linked.event_block_ends)

    run_source(source, dialect="mintmt", on_start=keep)
    return found[0]


def test_each_event_block_runs_from_its_first_statement_to_its_end_event() -> None:
    # pcs: 0 Dim, 1 Event, 2 hits = .., 3 End Event, 4 Event, 5 hits = .., 6 hits = .., 7 End Event, 8 Print
    source = (
        "Dim hits\nEvent Comms1\n  hits = hits + 1\nEnd Event\n"
        "Event Timer\n  hits = hits + 2\n  hits = hits * 2\nend   EVENT\nPrint hits\n"
    )
    assert _ends(source) == {2: 3, 5: 7}


def test_a_program_without_event_blocks_has_none() -> None:
    assert _ends("Dim x\nx = 1\n") == {}
