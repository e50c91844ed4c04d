"""MOVEBUFFERSIZE as MintMT's row ranges it: v4's 2 to 100 places (000:11053-11054, MT-1), whole ones only.

A buffer holds whole moves, and the row ``mint check`` reads prints no decimal part (MT-1), so 2.5 is
error 3 in both tools; v4's writer, whose guide prints no table for the keyword, takes it and keeps 2.
"""

from __future__ import annotations

from mintlang.runtime.keywords import Channels, KeywordTable, Values
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.ranges import check_range, table_bounds


def install(table: KeywordTable, motion: Motion) -> None:
    """Wrap v4's MOVEBUFFERSIZE writer in ``table`` so every value is checked against MintMT's row first."""
    access = table.get("MOVEBUFFERSIZE")
    if access is None or access.write is None:
        return
    resize = access.write
    limits = table_bounds("MOVEBUFFERSIZE", table.controller, table.dialect)

    def write(channels: Channels | None, values: Values) -> bool:
        for axis, value in zip(motion.addressed(channels), values, strict=False):
            if value is not None:
                check_range("MOVEBUFFERSIZE", value, limits, axis.number)
        return resize(channels, values)

    table.replace("MOVEBUFFERSIZE", write=write)
