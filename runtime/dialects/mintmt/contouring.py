"""CONTOURPARAMETER: MintMT's contouring settings by index; index 0 is the inter-vector angle (004:220-236).

The note names only index 0, the angle in degrees above which the join of two
vectors or arcs becomes a stop point: v4 keeps it as CONTOURANGLE, so index 0
writes that. Any other index is not simulated (mintlang/MINTMT.md).
"""

from __future__ import annotations

from mintlang.runtime.errors import NotSimulated
from mintlang.runtime.keywords import Channels, KeywordTable, Values

INTER_VECTOR_ANGLE = 0


def install(table: KeywordTable) -> None:
    angle = table.get("CONTOURANGLE")
    assert angle is not None and angle.write is not None, "v4's contouring registers CONTOURANGLE"
    write_angle = angle.write

    def write(channels: Channels | None, indices: tuple[int, ...], values: Values) -> bool:
        if indices != (INTER_VECTOR_ANGLE,):
            raise NotSimulated("CONTOURPARAMETER", f"index {', '.join(map(str, indices))}")
        return write_angle(channels, values)

    table.register("CONTOURPARAMETER", indexed_write=write)
