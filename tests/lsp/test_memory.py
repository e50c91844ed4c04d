"""Memory stays flat over a long editing session.

pygls filed every notification's handler in its table of requests in flight
and never took it out: 3 KB an edit, 59 MB growing to 113 MB over 18,000
edits of a document whose size never changed. Here a program is edited
20,000 times, each edit checked and its diagnostics pushed, and the server's
resident memory after 20,000 edits must be within 10 % of what it was after
2,000 (the caches are warm by then). About half a minute: marked ``slow``, which CI
runs and ``-m 'not slow'`` skips.
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from lsprotocol import types

from tests.lsp.conftest import change, document, open_document, uri_of

pytestmark = [
    pytest.mark.asyncio,
    pytest.mark.slow,
    pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads the server's RSS from /proc"),
]
EDITS, WARM = 20_000, 2_000
PROGRAM = (
    "DIM count = 0\nDIM target = 10\nLOOP\n  count = count + 1\n  IF count > target THEN EXIT\nENDL\nPRINT count\n"
)


def resident_kb(pid: int) -> int:
    for line in Path(f"/proc/{pid}/status").read_text(encoding="ascii").splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1])
    raise AssertionError("no VmRSS")


async def test_memory_is_flat_over_twenty_thousand_edits(neovim, tmp_path):
    uri = uri_of(tmp_path / "typing.mnt")
    await open_document(neovim, uri, PROGRAM)
    hover = types.HoverParams(text_document=document(uri), position=types.Position(line=0, character=5))
    warm = 0
    for edit in range(1, EDITS + 1):  # type a character into a name and take it out again
        if edit % 2:
            change(neovim, uri, edit + 1, ((3, 2), (3, 2)), "x")
        else:
            change(neovim, uri, edit + 1, ((3, 2), (3, 3)), "")
        if edit % 500 == 0:
            await neovim.text_document_hover_async(hover)  # the server has taken every edit so far
            neovim.diagnostics.clear()
        if edit == WARM:
            warm = resident_kb(neovim._server.pid)
    final = resident_kb(neovim._server.pid)
    assert final <= warm * 1.10, f"RSS {warm} kB after {WARM} edits, {final} kB after {EDITS}"
