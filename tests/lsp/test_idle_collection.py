"""The server collects cyclic garbage after a pause in its analyses, never during one."""

from __future__ import annotations

import asyncio
import gc
import weakref

import pytest

from mintlang.lsp.memory import IdleCollector


class _Cycle:
    def __init__(self) -> None:
        self.me = self


def test_arming_outside_an_event_loop_schedules_nothing():
    collector = IdleCollector(idle_s=0)
    collector.arm()
    assert collector.due is None


@pytest.mark.asyncio
async def test_each_analysis_postpones_the_collection():
    collector = IdleCollector(idle_s=60)
    collector.arm()
    first = collector.due
    await asyncio.sleep(0.01)
    collector.arm()
    assert first is not None and collector.due is not None and collector.due > first


@pytest.mark.asyncio
async def test_collects_cycles_once_idle():
    collector = IdleCollector(idle_s=0)
    was_enabled = gc.isenabled()
    gc.disable()  # as the server runs
    try:
        garbage = weakref.ref(_Cycle())  # unreachable, but only the collector can free a cycle
        collector.arm()
        for _ in range(200):
            if garbage() is None:
                break
            await asyncio.sleep(0.01)
        assert garbage() is None
        assert collector.due is None
    finally:
        if was_enabled:
            gc.enable()
