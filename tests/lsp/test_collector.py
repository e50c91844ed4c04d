"""The server freezes each analysis out of the garbage collector's scans and collects in full when idle."""

from __future__ import annotations

import asyncio
import gc
import weakref
from collections.abc import Iterator

import pytest

from mintlang.allocation import thaw_held
from mintlang.lsp.collector import Collector


class _Node:
    """Something that can sit in a reference cycle and be watched with a weak reference."""

    other: object = None


@pytest.fixture(autouse=True)
def thawed() -> Iterator[None]:
    yield
    thaw_held()  # leave the test process's collector as it found it


def garbage_cycle() -> weakref.ref[_Node]:
    first, second = _Node(), _Node()
    first.other, second.other = second, first
    return weakref.ref(first)


def test_an_analysis_is_frozen_out_of_the_scans() -> None:
    thaw_held()
    Collector().analysed()
    assert gc.get_freeze_count() > 0


def test_a_cycle_hidden_by_a_freeze_is_collected_once_the_server_is_idle() -> None:
    async def session() -> tuple[bool, bool]:
        collector = Collector(idle_s=0.05)
        watched = garbage_cycle()  # garbage, but a cycle: only the collector can free it
        collector.analysed()  # frozen with everything else
        gc.collect()
        hidden = watched() is not None
        await asyncio.sleep(0.2)
        return hidden, watched() is None

    hidden, freed = asyncio.run(session())
    assert hidden and freed


def test_each_new_analysis_postpones_the_full_collection() -> None:
    async def session() -> bool:
        collector = Collector(idle_s=0.5)
        watched = garbage_cycle()
        collector.analysed()
        for _ in range(7):  # typing for 0.7 s, an analysis every 0.1 s: never 0.5 s of quiet
            await asyncio.sleep(0.1)
            collector.analysed()
        return watched() is not None

    assert asyncio.run(session())


def test_long_typing_still_gets_a_full_collection_within_the_limit() -> None:
    async def session() -> bool:
        collector = Collector(idle_s=0.5, at_most_s=0.3)
        watched = garbage_cycle()
        collector.analysed()
        for _ in range(7):  # never 0.5 s of quiet, but 0.7 s in all: the 0.3 s limit passes
            await asyncio.sleep(0.1)
            collector.analysed()
        return watched() is None

    assert asyncio.run(session())
