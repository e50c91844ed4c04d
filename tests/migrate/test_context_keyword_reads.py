"""``Context.keyword_reads``: the uses of keywords that read their value, and only those, in line order."""

from __future__ import annotations

from mintlang.migrate.api import DEFAULT_CONTROLLER
from mintlang.migrate.context import Context
from mintlang.semantic.index import Use
from mintlang.semantic.units import Unit

PROGRAM = "MOVEA.0 = 10 : GO.0\na = MOVEA.0\nPRINT MOVEA.1, POS.1\nPAUSE IDLE.0\nMOVEA.1 = a + 1\n"


def _found(question: str, *keywords: str) -> list[tuple[int, str, Use]]:
    """(line, keyword, use) of each use ``Context.<question>(*keywords)`` yields for ``PROGRAM``."""
    context = Context.build({Unit.PROGRAM: PROGRAM}, str(DEFAULT_CONTROLLER))
    uses = getattr(context, question)(*keywords)
    return [(file.line_number(use.keyword.span.start), use.keyword.keyword, use.use) for file, use in uses]


def test_the_reads_of_a_keyword_and_not_its_writes() -> None:
    assert _found("keyword_reads", "MOVEA") == [(2, "MOVEA", Use.READ), (3, "MOVEA", Use.READ)]
    assert _found("keyword_uses", "MOVEA") == [
        (1, "MOVEA", Use.WRITE),
        (2, "MOVEA", Use.READ),
        (3, "MOVEA", Use.READ),
        (5, "MOVEA", Use.WRITE),
    ]


def test_the_reads_of_several_keywords_in_line_order() -> None:
    assert _found("keyword_reads", "POS", "MOVEA", "IDLE") == [
        (2, "MOVEA", Use.READ),
        (3, "MOVEA", Use.READ),
        (3, "POS", Use.READ),
        (4, "IDLE", Use.READ),
    ]


def test_a_command_is_no_read() -> None:
    assert _found("keyword_reads", "GO") == []
