"""Every MintMT listing of the move buffer note (AN00117) and the comms array note reads and checks as written.

The files under ``tests/corpus/mintmt/`` are the listings as the notes print
them (departures are noted in each header); a file with no ``expect`` line
must check without an error, the others give exactly the errors named.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang import Severity
from tests.corpus_files import CorpusCase, cases

LISTINGS = cases("mintmt")


def test_every_listing_of_both_notes_is_in_the_corpus() -> None:
    # 004 prints 16 listings of MintMT code (lines 31-302), 002 prints four (lines 27-85).
    move_buffer = [case for case in LISTINGS if "an00117" in case.name]
    comms = [case for case in LISTINGS if "comms" in case.name]
    assert (len(move_buffer), len(comms)) == (16, 4)


@pytest.mark.parametrize("case", LISTINGS, ids=lambda case: case.name)
def test_listing_round_trips_byte_exact(case: CorpusCase) -> None:
    document = mintlang.parse(case.source, dialect="mintmt")
    assert "".join(token.text for token in document.tokens) == case.source


@pytest.mark.parametrize("case", LISTINGS, ids=lambda case: case.name)
def test_listing_checks_as_the_note_implies(case: CorpusCase) -> None:
    analysis = mintlang.check_application(case.source, dialect=case.dialect, controller=case.controller)
    index = mintlang.LineIndex(case.source)
    errors = {
        (diagnostic.code, index.position(diagnostic.span.start).line)
        for diagnostic in analysis.program
        if diagnostic.severity is Severity.ERROR and not (case.fragment and diagnostic.code == "E3001")
    }
    assert errors == set(case.expected)


def test_the_notes_misprints_get_a_did_you_mean_with_a_fix() -> None:
    analysis = mintlang.check_application("VECTRR(0,1) = 10, 10\nCIRCLR(0,1) = -5, 5, 180\n", dialect="mintmt")
    messages = [(d.code, d.message.split(": ", 1)[1], d.fixes[0].title) for d in analysis.program]
    assert messages == [
        ("E3007", "'VECTRR' is not a keyword (did you mean 'VECTORR'?)", "Replace with VECTORR"),
        ("E3007", "'CIRCLR' is not a keyword (did you mean 'CIRCLER'?)", "Replace with CIRCLER"),
    ]
