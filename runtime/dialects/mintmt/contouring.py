"""CONTOURPARAMETER: MintMT's contouring settings by index; index 0 is the inter-vector angle (004:220-236).

The note names only index 0, the angle in degrees above which the join of two
vectors or arcs becomes a stop point: v4 keeps it as CONTOURANGLE, so index 0
writes and reads that, 15 degrees until written (000:8527). Any other index is
not simulated (mintlang/MINTMT.md).
"""

from __future__ import annotations

from mintlang.keyworddb.supplements import INDEXED_AS
from mintlang.runtime.errors import NotSimulated
from mintlang.runtime.keywords import Channels, KeywordAccess, KeywordTable, Values


def install(table: KeywordTable) -> None:
    def written(indices: tuple[int, ...]) -> KeywordAccess:
        """The v4 keyword an index stands for, its table's range and default (mint check reads them too)."""
        name = INDEXED_AS.get(("CONTOURPARAMETER", *indices))  # type: ignore[arg-type]
        access = table.get(name) if name is not None else None
        if access is None:
            raise NotSimulated("CONTOURPARAMETER", f"index {', '.join(map(str, indices))}")
        return access

    def write(channels: Channels | None, indices: tuple[int, ...], values: Values) -> bool:
        access = written(indices)
        assert access.write is not None, "an index stands for a parameter, written and read"
        return access.write(channels, values)

    def read(channel: int | None, indices: tuple[int, ...]) -> float:
        access = written(indices)
        assert access.read is not None, "an index stands for a parameter, written and read"
        return access.read(channel)

    table.register("CONTOURPARAMETER", indexed_write=write, indexed_read=read)
