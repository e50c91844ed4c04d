"""Where a statement takes a name it writes, FOR's counter (FOR <variable> = ..., 000:10889) as INPUT's variable
(000:12212), completion offers the names that can stand there: the variables and arrays, and the macros whose text
is a name. A keyword is no counter (000:18449-18451), and a macro standing for a number puts the number where the
name goes (the controller reads a macro's text in its place, 000:9110): mint check's syntax error 2003."""

from __future__ import annotations

import pytest

from tests.lsp.conftest import SHARED, open_document, uri_of
from tests.lsp.test_completion import labels_at

DECLARED = "DIM a\nDIM table(4)\nDEFINE counter = a\nDEFINE fast = 2000\n"


@SHARED
@pytest.mark.parametrize(
    "line",
    [
        pytest.param("FOR ", id="for"),
        pytest.param("FOR co", id="for-a-name-begun"),
        pytest.param("IF a THEN FOR ", id="for-after-then"),
        pytest.param("INPUT ", id="input"),
        pytest.param('INPUT #1 "Count? ", ', id="input-after-terminal-and-prompt"),
    ],
)
async def test_the_names_a_statement_can_fill_are_offered_only(shared_client, tmp_path, line):
    text = f"{DECLARED}{line}\n"
    uri = uri_of(tmp_path / "fills.mnt")
    await open_document(shared_client, uri, text)
    assert set(await labels_at(shared_client, uri, text, line, len(line))) == {"a", "table", "counter"}
