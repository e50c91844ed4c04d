"""Pausing the cyclic garbage collector while building large acyclic structures.

Parsing and checking allocate hundreds of thousands of small objects (tokens,
spans, nodes) and free none of them until the document is dropped. Each
allocation burst triggers collections that walk everything allocated so far,
which doubled the cost of a check. The structures hold no reference cycles,
so reference counting frees them; the collector is paused, not needed.

What a paused run leaves alive (per-line caches, a result kept for the rest of
the process) would still be walked once the collector runs again: every object
allocated meanwhile sits in its youngest generation, and the first collection
scans them all (0.2 s after a 10,000-line migration). ``kept_without_collector``
hands them to the oldest generation instead, which only a full collection scans.
"""

from __future__ import annotations

import gc
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from functools import wraps
from typing import ParamSpec, TypeVar

P = ParamSpec("P")
R = TypeVar("R")


@contextmanager
def collector_paused() -> Iterator[None]:
    """Pause cyclic garbage collection for the block (re-entrant)."""
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was_enabled:
            gc.enable()


def without_collector(function: Callable[P, R]) -> Callable[P, R]:
    """Decorator form of ``collector_paused``."""

    @wraps(function)
    def wrapper(*args: P.args, **kwargs: P.kwargs) -> R:
        with collector_paused():
            return function(*args, **kwargs)

    return wrapper


def kept_without_collector(function: Callable[P, R]) -> Callable[P, R]:
    """``without_collector`` for a function whose structures outlive the call: when it returns,
    what the collector tracks goes to its oldest generation unscanned. If something else keeps
    objects frozen (the language server, until it is idle), they join those, which their owner
    thaws and collects; otherwise freezing and thawing at once is the move (both O(1))."""

    @wraps(function)
    def wrapper(*args: P.args, **kwargs: P.kwargs) -> R:
        with collector_paused():
            try:
                return function(*args, **kwargs)
            finally:
                others_frozen = gc.get_freeze_count() > 0
                gc.freeze()
                if not others_frozen:
                    gc.unfreeze()

    return wrapper
