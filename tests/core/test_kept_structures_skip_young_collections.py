"""What a run builds to keep goes to the collector's oldest generation, not through the young ones.

The first collection after a paused run would otherwise walk everything the run
left alive (per-line caches, the result). A process whose objects another part
holds frozen (the language server) keeps them frozen: the run's join them.
"""

from __future__ import annotations

import gc

from mintlang.allocation import hold_frozen, kept_without_collector, thaw_held


class _Kept:
    """A tracked object a run leaves alive."""


@kept_without_collector
def _build(count: int) -> list[_Kept]:
    assert not gc.isenabled(), "the collector is paused during the run"
    return [_Kept() for _ in range(count)]


def _generation_of(item: object) -> int | None:
    for generation in range(3):
        if any(found is item for found in gc.get_objects(generation)):
            return generation
    return None


def test_survivors_are_in_the_oldest_generation_and_the_collector_runs_again() -> None:
    was_enabled = gc.isenabled()
    gc.enable()
    try:
        kept = _build(1_000)
        assert gc.isenabled()
        assert _generation_of(kept[0]) == 2
        assert _generation_of(kept[-1]) == 2
        assert gc.get_freeze_count() == 0
    finally:
        if not was_enabled:
            gc.disable()


def test_objects_held_frozen_by_another_part_stay_frozen_and_the_run_joins_them() -> None:
    hold_frozen()
    try:
        frozen = gc.get_freeze_count()
        kept = _build(10)
        assert gc.get_freeze_count() >= frozen + len(kept)
        assert _generation_of(kept[0]) is None  # frozen: in no generation the collector scans
    finally:
        thaw_held()
    assert gc.get_freeze_count() == 0
