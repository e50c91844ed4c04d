"""CONTOURPARAMETER: MintMT's contouring settings by index; index 0 is the inter-vector angle (004:220-236).

The note names only index 0, the angle in degrees above which the join of two
vectors or arcs becomes a stop point: v4 keeps it as CONTOURANGLE, so index 0
writes that. Any other index is not simulated (mintlang/MINTMT.md).
"""

from __future__ import annotations

from mintlang.keyworddb.supplements import INDEXED_AS
from mintlang.runtime.errors import NotSimulated
from mintlang.runtime.keywords import Channels, KeywordTable, Values


def install(table: KeywordTable) -> None:
    def write(channels: Channels | None, indices: tuple[int, ...], values: Values) -> bool:
        written = INDEXED_AS.get(("CONTOURPARAMETER", *indices))  # type: ignore[arg-type]
        access = table.get(written) if written is not None else None
        if access is None or access.write is None:
            raise NotSimulated("CONTOURPARAMETER", f"index {', '.join(map(str, indices))}")
        return access.write(channels, values)  # v4's writer, its table's range (mint check reads it too)

    table.register("CONTOURPARAMETER", indexed_write=write)
