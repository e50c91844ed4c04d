"""Keeping Python's cyclic garbage collector off the path of the editor's next request.

An analysis builds a few hundred thousand objects with the collector paused
(``mintlang.allocation``). Once it runs again, the first request to allocate
(the semantic tokens or a completion that follow every edit) pays for
scanning all of them: 20-150 ms on a 5,000-line program. The trees are acyclic
and live until the next version replaces them, so the server freezes them out
of the collector's sight as soon as they are built; reference counting still
frees them. Freezing would also hide any garbage cycle alive at that moment
(an asyncio task, an exception's traceback), so once the editor has been quiet
for a while everything is thawed and collected in full, where nobody waits.
"""

from __future__ import annotations

import asyncio
import gc

IDLE_S = 5.0  # quiet time before the full collection


class Collector:
    """Freezes each new analysis; a full collection follows when the server has been idle ``idle_s``."""

    def __init__(self, idle_s: float = IDLE_S) -> None:
        self.idle_s = idle_s
        self._pending: asyncio.TimerHandle | None = None

    def analysed(self) -> None:
        """A snapshot was just built: freeze it, and postpone the full collection."""
        gc.freeze()
        if self._pending is not None:
            self._pending.cancel()
            self._pending = None
        try:
            loop = asyncio.get_running_loop()
        except RuntimeError:  # analysed outside the server's loop: nothing to schedule
            return
        self._pending = loop.call_later(self.idle_s, self.collect)

    def collect(self) -> None:
        """Everything thawed and collected in full, then frozen again until the next edit."""
        self._pending = None
        gc.unfreeze()
        gc.collect()
        gc.freeze()
