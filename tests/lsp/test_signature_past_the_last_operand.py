"""An operand past the last a format takes has no parameter to highlight: the format is not offered for it.
An ``activeParameter`` outside the signature's parameters means the first one to the client (LSP 3.17,
SignatureHelp), which would mark the first operand as the one being written."""

from __future__ import annotations

import pytest

from tests.lsp.conftest import SHARED, open_document, uri_of
from tests.lsp.test_signature import active, help_at

pytestmark = pytest.mark.asyncio


@SHARED
@pytest.mark.parametrize(
    "line",
    [
        pytest.param("a = ABS(1, ", id="abs-takes-one-value"),  # v = ABS (<expression>) (000:6124)
        pytest.param("a = POW(2, 3, ", id="pow-takes-two"),  # v = POW(x, y) (000:15152)
        # CIRCLEA[axis0,axis1] = <centre0>,<centre1>,<angle> (000:8152): a fourth value is none of them
        pytest.param("CIRCLEA[0,1] = 1, 2, 3, ", id="circlea-takes-three"),
    ],
)
async def test_no_format_is_offered_past_its_last_operand(shared_client, tmp_path, line):
    text = f"DIM a\n{line}\n"
    uri = uri_of(tmp_path / "past.mnt")
    await open_document(shared_client, uri, text)
    assert await help_at(shared_client, uri, text, line, len(line)) is None


@SHARED
@pytest.mark.parametrize(
    ("line", "parameter"),
    [
        ("a = POW(2, ", "y"),  # the last operand is still highlighted
        ("MOVEA[0,1,2] = 1, 2, 3, ", "<expression ..."),  # a repeated operand takes every further value
        ("PRINT a, a, a, a, ", "modifier argument"),  # as many values as the line holds (000:15305)
    ],
)
async def test_the_last_operand_and_a_repeated_one_are_still_shown(shared_client, tmp_path, line, parameter):
    text = f"DIM a\n{line}\n"
    uri = uri_of(tmp_path / "last.mnt")
    await open_document(shared_client, uri, text)
    assert (await active(shared_client, uri, text, line, len(line)))[1] == parameter
