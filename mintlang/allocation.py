"""Pausing the cyclic garbage collector while building large acyclic structures.

Parsing and checking allocate hundreds of thousands of small objects (tokens,
spans, nodes) and free none of them until the document is dropped. Each
allocation burst triggers collections that walk everything allocated so far,
which doubled the cost of a check. The structures hold no reference cycles,
so reference counting frees them; the collector is paused, not needed.
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
