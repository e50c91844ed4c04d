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

At exit, the interpreter's own collections walk everything the process still
holds: ``no_collection_at_exit`` spares the command-line tools that walk.
"""

from __future__ import annotations

import atexit
import gc
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from functools import cache, wraps
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


class _Holding:
    """Whether a part of the process keeps objects frozen until it thaws them (``hold_frozen``).

    Known here rather than asked of ``gc.get_freeze_count()``, which counts by walking every
    frozen object: 20 ms a call with two million frozen."""

    frozen = False


def hold_frozen() -> None:
    """Freeze everything alive now for an owner that will ``thaw_held`` it (the language server,
    until it is idle); ``kept_without_collector`` leaves what it keeps frozen with it meanwhile."""
    gc.freeze()
    _Holding.frozen = True


def thaw_held() -> None:
    """Give what ``hold_frozen`` froze back to the collector's oldest generation."""
    gc.unfreeze()
    _Holding.frozen = False


def kept_without_collector(function: Callable[P, R]) -> Callable[P, R]:
    """``without_collector`` for a function whose structures outlive the call: when it returns,
    what the collector tracks goes to its oldest generation unscanned. If a part of the process
    holds objects frozen (``hold_frozen``), they join those, which their owner thaws and collects;
    otherwise freezing and thawing at once is the move (both O(1))."""

    @wraps(function)
    def wrapper(*args: P.args, **kwargs: P.kwargs) -> R:
        with collector_paused_and_kept():
            return function(*args, **kwargs)

    return wrapper


@contextmanager
def collector_paused_and_kept() -> Iterator[None]:
    """The block form of ``kept_without_collector``: for imports, say, whose modules live as long as the process."""
    with collector_paused():
        try:
            yield
        finally:
            gc.freeze()
            if not _Holding.frozen:
                gc.unfreeze()


@cache  # once per process
def no_collection_at_exit() -> None:
    """Let the interpreter exit without its collector walking every object still alive.

    Finalizing, CPython collects while it clears the modules, over every object the
    process holds (classes, the keyword database, the parser's tables, caches): a fifth
    of the CPU time of a one-line ``mint check``. Frozen first, in an ``atexit`` handler
    (which runs before), they are skipped. Reference cycles that are garbage by then are
    left to the operating system, as is everything still referenced: nothing the tools
    write depends on a finalizer, their files are closed before they exit."""
    atexit.register(gc.freeze)
