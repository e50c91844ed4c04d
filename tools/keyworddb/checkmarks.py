"""Decode the check-mark columns the PDF conversion left behind.

Every tick became U+FFFD and every empty cell became an empty string, with one
space between cells; so a run of ticks and spaces splits on single spaces into
the cells again.  The conversion sometimes adds a space after a description;
beyond that one known slip, callers receive ``None`` when the count is wrong.
"""

from __future__ import annotations

import re

from mintlang.keyworddb.model import Controller

TICK = "\ufffd"
V4_ORDER = (
    Controller.NEXTMOVE_PCI,
    Controller.NEXTMOVE_PC,
    Controller.NEXTMOVE_BX,
    Controller.MINTDRIVE,
    Controller.SERVONODE51,
)
"""Column order of the "Controllers Supported" rows in chapter 10."""

QUICKREF_ORDER = (
    Controller.NEXTMOVE_PCI,
    Controller.NEXTMOVE_PC,
    Controller.NEXTMOVE_BX,
    Controller.SERVONODE51,
    Controller.MINTDRIVE,
)
"""Column order of the chapter 11 tables: PCI PC BX SN MD."""

_TRAILING_CELLS = re.compile(r"(?:^|(?<=\S) )(?P<cells>[ \ufffd]*\ufffd[ \ufffd]*|\s{4,})$")


def split_cells(text: str, count: int) -> list[bool] | None:
    """Tick flags of ``count`` single-space separated cells, or None if ambiguous."""
    if text.endswith(" "):
        text = text[:-1]
    cells = text.split(" ")
    if len(cells) == count + 1 and cells[0] == "":
        cells = cells[1:]  # a description ending in a space leaves one extra leading separator
    if len(cells) != count or any(cell not in ("", TICK) for cell in cells):
        return None
    return [cell == TICK for cell in cells]


def controllers_of(flags: list[bool], order: tuple[Controller, ...]) -> tuple[Controller, ...]:
    """The ticked controllers, in the enum's order whatever the column order."""
    ticked = {c for c, flag in zip(order, flags, strict=True) if flag}
    return tuple(c for c in Controller if c in ticked)


def trailing_cells(line: str) -> tuple[str, str] | None:
    """Split a table row into its text and the trailing run of check-mark cells."""
    match = _TRAILING_CELLS.search(line)
    if not match:
        return None
    return line[: match.start()].rstrip(), match["cells"]
