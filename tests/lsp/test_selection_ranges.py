"""Expand selection: word, expressions, statement, line, blocks, subroutine, file."""

from __future__ import annotations

from itertools import pairwise

import pytest
from lsprotocol import types

from tests.lsp.conftest import corpus, document, open_document, position, uri_of

pytestmark = pytest.mark.asyncio
XY = corpus("ch01_l0144_xy_example.mnt")  # the guide's XY table program (line 144)


def texts(text: str, chain: types.SelectionRange | None) -> list[str]:
    starts = [0, *(index + 1 for index, character in enumerate(text) if character == "\n")]
    found = []
    while chain is not None:
        start, end = chain.range.start, chain.range.end
        found.append(text[starts[start.line] + start.character : starts[end.line] + end.character])
        chain = chain.parent
    return found


async def test_from_an_array_element_to_the_whole_program(client, tmp_path):
    uri = uri_of(tmp_path / "xy.mnt")
    await open_document(client, uri, XY)
    [chain] = await client.text_document_selection_range_async(
        types.SelectionRangeParams(text_document=document(uri), positions=[position(XY, "xpos(a),", 1)])
    )
    found = texts(XY, chain)
    lines = XY.splitlines()
    assert found[:4] == ["xpos", "xpos(a)", "MOVEA[0,1] = xpos(a),ypos(a)", lines[27]]
    assert found[4] == "\n".join(lines[25:35])  # FOR a = 1 to 10 .. NEXT
    assert found[5] == "\n".join(lines[23:39])  # LOOP .. ENDL
    assert found[6].startswith("#main\n") and found[6].endswith("RETURN\n")  # the subroutine
    assert found[7] == XY
    for inner, outer in pairwise(found):
        assert inner in outer and inner != outer  # every step grows the selection


async def test_one_chain_per_position(client, tmp_path):
    text = "DIM a\na = (a + 1) * 2\n"
    uri = uri_of(tmp_path / "expression.mnt")
    await open_document(client, uri, text)
    chains = await client.text_document_selection_range_async(
        types.SelectionRangeParams(
            text_document=document(uri), positions=[position(text, "a + 1"), position(text, "DIM")]
        )
    )
    assert texts(text, chains[0]) == ["a", "a + 1", "(a + 1)", "(a + 1) * 2", "a = (a + 1) * 2", text]
    assert texts(text, chains[1]) == ["DIM", "DIM a", text]
