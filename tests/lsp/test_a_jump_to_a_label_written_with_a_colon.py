"""A jump to a label written as other BASICs write it (``Init:``) is fixed by writing that label with its hash.

A Mint label is ``#Init`` first on its line (000:1843-1844, 1871-1872), so ``GOTO Init`` finds no label
(3004) while ``Init:`` is keyword not defined (3007). Creating ``#Init`` at the end of the file, as for a
label nowhere written, made two labels once the 3007 fix wrote the hash: 'label #Init is already defined'.
The jump's diagnostic is offered the same fix as the line that means the label, and no other.
"""

from __future__ import annotations

import pytest

from tests.lsp.conftest import open_document, uri_of
from tests.lsp.test_quick_fixes import applied, fixes

pytestmark = pytest.mark.asyncio


async def test_the_jump_is_offered_the_hash_on_the_labels_line(client, tmp_path):
    text = "Init:\nPRINT 1\nGOTO Init\n"
    uri = uri_of(tmp_path / "cell.mnt")
    diagnostics = await open_document(client, uri, text)
    [jump] = [diagnostic for diagnostic in diagnostics if diagnostic.code == "E3004"]
    assert "Init:" in jump.message  # the message points at the line that meant it
    found = await fixes(client, uri, [jump], 2)
    titles = {title for title in found if not title.startswith("Ignore")}
    assert titles == {"Write the label with a hash"}
    assert applied(text, found["Write the label with a hash"], uri) == "#Init\nPRINT 1\nGOTO Init\n"
