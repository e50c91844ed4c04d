"""A label may be digits alone (any combination of alphanumeric characters, 000:1843: ``#123``, ``GOSUB 123``, as
rename accepts it): the word pattern sent with the linked ranges, which the editor holds their text to (LSP 3.17,
LinkedEditingRanges), admits such a name, so that the linked ranges of ``#123`` are not invalid from the start."""

from __future__ import annotations

import re

import pytest

from tests.lsp.conftest import open_document, uri_of
from tests.lsp.test_linked_editing import ranges_at

pytestmark = pytest.mark.asyncio


async def test_the_word_pattern_admits_a_label_of_digits(client, tmp_path):
    text = "GOSUB 123\nEND\n#123\nRETURN\n"
    uri = uri_of(tmp_path / "numbered.mnt")
    await open_document(client, uri, text)
    found = await ranges_at(client, uri, text, "#123", 2)
    assert [(r.start.line, r.start.character, r.end.character) for r in found.ranges] == [(2, 1, 4), (0, 6, 9)]
    assert re.fullmatch(found.word_pattern, "123") and re.fullmatch(found.word_pattern, "456")
    assert re.fullmatch(found.word_pattern, "step_2")  # a name, as before
    assert not re.fullmatch(found.word_pattern, "2step")  # neither a name nor a number
