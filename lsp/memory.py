"""Cyclic garbage collection when the user pauses, not while they type.

An analysis allocates a few hundred thousand objects that reference counting
frees (syntax trees, models and diagnostics hold no cycles). Left automatic,
the collector runs in the middle of the next analysis and walks every live
object of every open document: on a 5,000-line program that was about a third
of the time from a keystroke to its diagnostics. The server therefore turns
automatic collection off (``take_over``) and collects once it has been idle
for a moment after its last analysis, so cycles other libraries create are
still reclaimed.
"""

from __future__ import annotations

import asyncio
import gc
import logging
import time

log = logging.getLogger(__name__)

IDLE_S = 2.0  # a pause in typing; collecting then cannot delay an answer the user is waiting for


class IdleCollector:
    """Collects ``idle_s`` after the last call of ``arm``; each call postpones it."""

    def __init__(self, idle_s: float = IDLE_S) -> None:
        self.idle_s = idle_s
        self._pending: asyncio.TimerHandle | None = None

    @staticmethod
    def take_over() -> None:
        """Stop automatic collection for the rest of the process (the server's entry point calls this)."""
        gc.disable()

    def arm(self) -> None:
        try:
            loop = asyncio.get_running_loop()
        except RuntimeError:  # analysed outside the server's event loop (a test, a script): nothing to schedule
            return
        if self._pending is not None:
            self._pending.cancel()
        self._pending = loop.call_later(self.idle_s, self.collect)

    @property
    def due(self) -> float | None:
        """The event-loop time of the next collection, if one is scheduled."""
        return self._pending.when() if self._pending is not None else None

    def collect(self) -> int:
        """Collect now; the number of unreachable objects found."""
        self._pending = None
        start = time.perf_counter()
        found = gc.collect()
        log.debug("collected %d objects in %.1f ms while idle", found, (time.perf_counter() - start) * 1000)
        return found
