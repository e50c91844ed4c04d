"""Reference counts above labels, variables, arrays and macros, resolved when shown."""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import corpus, document, open_document, uri_of

pytestmark = pytest.mark.asyncio
XY = corpus("ch01_l0144_xy_example.mnt")  # the guide's XY table program (line 144)


async def resolved(client, uri) -> dict[int, types.Command]:
    """Per 0-based line, the resolved count lens (the run lens has its command already)."""
    found = await client.text_document_code_lens_async(types.CodeLensParams(text_document=document(uri)))
    counts = {}
    for lens in found:
        if lens.command is None:
            counts[lens.range.start.line] = (await client.code_lens_resolve_async(lens)).command
    return counts


async def test_labels_and_arrays_of_the_xy_program(client, tmp_path):
    uri = uri_of(tmp_path / "xy.mnt")
    await open_document(client, uri, XY)
    counts = await resolved(client, uri)
    titles = {line: command.title for line, command in counts.items()}
    # xpos, ypos (line 7, 8 of the guide's listing), #init, #main, a (DIM in #main)
    assert titles == {6: "1 reference", 7: "1 reference", 13: "2 references", 19: "1 reference", 20: "3 references"}
    assert counts[13].tooltip == "init: 2 in the program file"
    assert counts[13].command == ""  # a count to read: no command to run


async def test_uses_in_the_configuration_file_and_in_macro_texts_count(client, tmp_path):
    (tmp_path / "cell.cfg").write_text("DIM rate = 10\nDEFINE fast = SPEED.0 = rate * 2\n", encoding="utf-8")
    program = "PRINT rate\nfast\nDIM spare\n"
    uri = uri_of(tmp_path / "cell.mnt")
    await open_document(client, uri, program)
    counts = await resolved(client, uri)
    assert (counts[2].title, counts[2].tooltip) == ("0 references", "spare is never used")
    configuration = uri_of(tmp_path / "cell.cfg")
    await open_document(client, configuration, (tmp_path / "cell.cfg").read_text(encoding="utf-8"))
    counts = await resolved(client, configuration)
    assert counts[0].title == "2 references"  # in the macro's text once, and the program's PRINT
    assert counts[0].tooltip == "rate: 1 in the program file, 1 in the configuration file"
    assert counts[1].title == "1 reference"  # fast, used in the program
