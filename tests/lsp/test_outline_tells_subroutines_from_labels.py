"""The outline shows a label as a subroutine only when it is one: a GOSUB names it (000:1841-1850), or nothing
jumps to it yet (the guide shows subroutines alone, 000:961; mint check's flow reads such a label as a routine's
start too), or it is an event handler the controller calls (#ONERROR, 000:10987). A label only a GOTO names
(000:11187-11188) is a place in the code: a plain label, nested in the subroutine or handler it stands in (before
that one's RETURN), which then spans it. Every label was shown as a subroutine."""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import document, open_document, uri_of

pytestmark = pytest.mark.asyncio

SUBROUTINE, HANDLER, LABEL = types.SymbolKind.Function, types.SymbolKind.Event, types.SymbolKind.Key

Outlined = tuple[str, types.SymbolKind, str | None, int, int, tuple["Outlined", ...]]


def _outlined(symbols: list[types.DocumentSymbol]) -> list[Outlined]:
    """Each symbol as (name, kind, detail, first line, line its range ends on, children)."""
    return [
        (s.name, s.kind, s.detail, s.range.start.line, s.range.end.line, tuple(_outlined(s.children or [])))
        for s in symbols
    ]


async def _outline(client, tmp_path, text: str) -> list[Outlined]:
    uri = uri_of(tmp_path / "outline.mnt")
    await open_document(client, uri, text)
    symbols = await client.text_document_document_symbol_async(types.DocumentSymbolParams(text_document=document(uri)))
    return _outlined(symbols)


PROGRAM = """\
DIM n
GOSUB init
#more
  n = n + 1
  IF n < 10 THEN GOTO more
END
#init
  n = 0
#retry
  n = n + 1
  IF n < 3 THEN GOTO retry
RETURN
#ONERROR
#cleared
  IF ERR THEN GOTO cleared
RETURN
"""


async def test_gosub_targets_and_handlers_are_routines_and_goto_targets_labels(client, tmp_path):
    # the ranges end where the next line begins: #init's covers #retry, lines 6 to 11, so it ends on line 12
    assert await _outline(client, tmp_path, PROGRAM) == [
        ("n", types.SymbolKind.Variable, "variable", 0, 0, ()),
        ("#more", LABEL, "label", 2, 6, ()),
        ("#init", SUBROUTINE, "subroutine", 6, 12, (("#retry", LABEL, "label", 8, 12, ()),)),
        ("#ONERROR", HANDLER, "event handler", 12, 16, (("#cleared", LABEL, "label", 13, 16, ()),)),
    ]


async def test_a_label_after_a_subroutines_return_is_not_in_it(client, tmp_path):
    text = 'GOSUB work\nGOTO finish\n#work\n  PRINT "w"\nRETURN\n#finish\nEND\n#spare\nEND\n'
    assert await _outline(client, tmp_path, text) == [
        ("#work", SUBROUTINE, "subroutine", 2, 5, ()),
        ("#finish", LABEL, "label", 5, 7, ()),
        ("#spare", SUBROUTINE, "subroutine", 7, 9, ()),
    ]


async def test_a_return_inside_a_block_does_not_end_the_subroutine(client, tmp_path):
    text = "DIM n\nGOSUB work\nEND\n#work\n  IF n DO\n    RETURN\n  ENDIF\n#again\n  n = n - 1\n  GOTO again\n"
    outline = await _outline(client, tmp_path, text)
    assert outline[1] == ("#work", SUBROUTINE, "subroutine", 3, 10, (("#again", LABEL, "label", 7, 10, ()),))


async def test_a_gosub_in_a_macros_text_makes_a_subroutine(client, tmp_path):
    text = "DEFINE tidy = GOSUB clear\ntidy\nEND\n#clear\nRETURN\n"
    outline = await _outline(client, tmp_path, text)
    assert ("#clear", SUBROUTINE, "subroutine", 3, 5, ()) in outline
