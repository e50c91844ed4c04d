"""Completion in an axis keyword's square brackets offers what an axis there can be: a number or a simple
variable, never an expression (000:580-588: MOVER[a] is valid, MOVER[a+1] is not)."""

from __future__ import annotations

import pytest

from tests.lsp.conftest import open_document, uri_of
from tests.lsp.test_completion import labels_at

pytestmark = pytest.mark.asyncio

DECLARED = "DEFINE xAxis = 1\nDEFINE far = 40\nDEFINE pair = [0,1]\nDIM n = 1\nDIM table(3)\n"
NEXTMOVE_PCI_AXES = {str(axis) for axis in range(12)}  # axis number 0 ≤ x ≤ 11 on NextMove PCI (000:5613)


@pytest.mark.parametrize("written", ["SPEED[", "SPEED[0,", "a = POS[xA"])
async def test_the_axes_the_variables_and_the_macros_for_one_axis(client, tmp_path, written):
    text = DECLARED + written + "\n"
    uri = uri_of(tmp_path / "brackets.mnt")
    await open_document(client, uri, text)
    items = await labels_at(client, uri, text, written, len(written))
    # far is axis 40, which NextMove PCI lacks; pair is a list, and [[0,1]] no axis; an array takes an index
    assert set(items) == NEXTMOVE_PCI_AXES | {"n", "xAxis"}


@pytest.mark.parametrize(
    "written",
    [
        "SPEED[0 ",  # only "," or "]" can follow an axis
        "a = ADC[",  # a channel is written after the dot only: ADC.0 (000:560)
        "OUT[",
    ],
)
async def test_nothing_where_no_axis_can_come(client, tmp_path, written):
    text = DECLARED + written + "\n"
    uri = uri_of(tmp_path / "nothing.mnt")
    await open_document(client, uri, text)
    assert await labels_at(client, uri, text, written, len(written)) == {}


async def test_the_values_after_the_brackets_are_expressions_again(client, tmp_path):
    text = DECLARED + "SPEED[0,1] = \n"
    uri = uri_of(tmp_path / "values.mnt")
    await open_document(client, uri, text)
    items = await labels_at(client, uri, text, "SPEED[0,1] = ", 13)
    assert {"ABS", "POS", "n", "table"} <= set(items)
