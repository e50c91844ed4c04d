"""Keeping Python's cyclic garbage collector off the path of the editor's next request.

An analysis builds a few hundred thousand objects with the collector paused
(``mintlang.allocation``). Once it runs again, the first request to allocate
(the semantic tokens or a completion that follow every edit) pays for
scanning all of them: 20-150 ms on a 5,000-line program. The trees are acyclic
and live until the next version replaces them, so the server freezes them out
of the collector's sight as soon as they are built; reference counting still
frees them. Freezing would also hide any garbage cycle alive at that moment
(an asyncio task, an exception's traceback, a simulation's objects on its
worker thread: freezing is process-wide), so once the editor has been quiet for
a while everything is thawed and collected in full, where nobody waits, and
during long typing at least once every ``AT_MOST_S``.
"""

from __future__ import annotations

import asyncio
import gc

from mintlang.allocation import hold_frozen, thaw_held

IDLE_S = 5.0  # quiet time before the full collection
AT_MOST_S = 60.0  # the longest a frozen cycle waits, however long the typing goes on


class Collector:
    """Freezes each new analysis; a full collection follows once the server has been idle ``idle_s``,
    and no later than ``at_most_s`` after the first freeze since the last one."""

    def __init__(self, idle_s: float = IDLE_S, at_most_s: float = AT_MOST_S) -> None:
        self.idle_s = idle_s
        self.at_most_s = at_most_s
        self._pending: asyncio.TimerHandle | None = None
        self._first_freeze: float | None = None  # loop time of the first freeze since the last collection

    def analysed(self) -> None:
        """A snapshot was just built: freeze it, and postpone the full collection (within the limit)."""
        hold_frozen()
        if self._pending is not None:
            self._pending.cancel()
            self._pending = None
        try:
            loop = asyncio.get_running_loop()
        except RuntimeError:  # analysed outside the server's loop: nothing to schedule
            return
        now = loop.time()
        if self._first_freeze is None:
            self._first_freeze = now
        delay = min(self.idle_s, max(0.0, self._first_freeze + self.at_most_s - now))
        self._pending = loop.call_later(delay, self.collect)

    def collect(self) -> None:
        """Everything thawed and collected in full; the next analysis freezes again."""
        self._pending = None
        self._first_freeze = None
        thaw_held()
        gc.collect()
