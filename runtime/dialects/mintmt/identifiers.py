"""MOVEBUFFERID and MOVEBUFFERIDLAST: identifiers stored with the moves of the buffer (004:136-151, MT-12).

Written, MOVEBUFFERID is the identifier stored with every move loaded on that
axis from then on; read, it is the identifier of the move running, 0 while the
axis runs none. MOVEBUFFERIDLAST is the identifier of the last move started,
which stays once the motion has finished.
"""

from __future__ import annotations

from mintlang.runtime.keywords import KeywordTable, per_channel
from mintlang.runtime.motion.commands import Motion


def install(table: KeywordTable, motion: Motion) -> None:
    def write(channel: int | None, value: float) -> None:
        motion.axis(channel).load_ident = value

    def running(channel: int | None) -> float:
        axis = motion.watched(motion.axis(channel))
        return axis.last_ident if axis.move is not None else 0.0

    def last(channel: int | None) -> float:
        return motion.watched(motion.axis(channel)).last_ident

    table.register("MOVEBUFFERID", read=running, write=per_channel(write))
    table.register("MOVEBUFFERIDLAST", read=last)
