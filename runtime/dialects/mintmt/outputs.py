"""OUTX: one digital output channel, on or off (004:148), as v4's ``OUT.channel`` is."""

from __future__ import annotations

from mintlang.keyworddb.supplements import WRITTEN_AS
from mintlang.runtime.errors import MISSING_PARAMETER, MintError
from mintlang.runtime.keywords import Channels, KeywordTable, Values


def install(table: KeywordTable) -> None:
    out = table.get(WRITTEN_AS["OUTX"])  # its writer holds the value to OUT's range, as mint check does
    assert out is not None and out.read is not None and out.write is not None, "v4's I/O registers OUT"
    read_out, write_out = out.read, out.write

    def read(channel: int | None) -> float:
        if channel is None:
            raise MintError(MISSING_PARAMETER, detail="OUTX reads one channel: OUTX(0)")
        return read_out(channel)

    def write(channels: Channels | None, values: Values) -> bool:
        if channels is None:
            raise MintError(MISSING_PARAMETER, detail="OUTX sets one channel: OUTX(0) = 1")
        return write_out(channels, values)

    table.register("OUTX", read=read, write=write)
