"""A warning's message opens with its code's title once, whatever the letter case of the checker's detail."""

from __future__ import annotations

import pytest

from mintlang.codes import OWN_CODES
from tests.lsp.conftest import open_document, uri_of

pytestmark = pytest.mark.asyncio


async def test_typographic_quotes_are_named_once(client, tmp_path):
    diagnostics = await open_document(client, uri_of(tmp_path / "quotes.mnt"), "PRINT \u201cdone\u201d\n")
    [warning] = [d for d in diagnostics if d.code == "W101"]
    assert warning.message == 'Typographic quotes: the controller expects plain quotes (")'


async def test_every_warning_carries_its_title_once(client, tmp_path):
    text = "DIM unused\nPRINT \u201cx\u201d\nEND\nPRINT 1\n#never\nRETURN\n"
    diagnostics = await open_document(client, uri_of(tmp_path / "warnings.mnt"), text)
    own = [d for d in diagnostics if d.code in OWN_CODES]
    assert {d.code for d in own} == {"W101", "W103", "W104", "W106"}
    for warning in own:
        title = OWN_CODES[str(warning.code)]
        assert warning.message.startswith(f"{title}: ")
        assert warning.message.casefold().count(title.casefold()) == 1
