"""Which checkpoints a run keeps: all of the recent past, fewer and fewer further back, never more than ``LIMIT``.

The counts are worked out by hand from the thinning rule of
``runtime/debugger/checkpoints.py``: with ``DENSE`` = 2, a checkpoint ``age``
intervals old is kept one in ``2 ** level``, where ``level`` is the bit length
of ``age // 2``, less one (0 below an age of 4).
"""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from mintlang.runtime.debugger import checkpoints as module
from mintlang.runtime.debugger.checkpoints import Checkpoint, Checkpoints
from mintlang.runtime.snapshot import Snapshot


def _checkpoint(serial: int) -> Checkpoint:
    """The checkpoint numbered ``serial``, as if each interval held ten points."""
    return Checkpoint(
        serial, tick=serial, count=10 * serial, ticks=0, writes=0, blocked=None, hits={}, state=Snapshot(())
    )


def _run(serials: range) -> Checkpoints:
    kept = Checkpoints()
    for serial in serials:
        if kept.wanted(serial):
            kept.add(_checkpoint(serial))
    return kept


@pytest.fixture(autouse=True)
def _small(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(module, "DENSE", 2)
    monkeypatch.setattr(module, "LIMIT", 64)


def test_the_recent_ones_are_all_kept_and_the_older_ones_thinned_out() -> None:
    kept = _run(range(17))  # the newest is 16
    # ages 0-3 every one (16..13), 4-7 every second (12, 10), 8-15 every fourth (8, 4), 16 every eighth (0)
    assert [checkpoint.serial for checkpoint in kept.kept] == [0, 4, 8, 10, 12, 13, 14, 15, 16]


def test_a_checkpoint_thinned_out_is_not_wanted_again_when_a_re_run_passes_its_place() -> None:
    kept = _run(range(17))
    assert not kept.wanted(11)  # 5 intervals old: one in two is kept, and 11 is odd
    assert not kept.wanted(12)  # already kept
    assert kept.wanted(17)


def test_going_back_starts_from_the_latest_checkpoint_at_or_before_the_point() -> None:
    kept = _run(range(17))
    assert kept.latest(105).serial == 10  # points 100-109 follow checkpoint 10
    assert kept.latest(99).serial == 8
    assert kept.latest(0).serial == 0
    assert _run(range(0)).latest(5) is None


def test_a_change_at_a_point_forgets_the_checkpoints_after_it() -> None:
    kept = _run(range(17))
    kept.forget_after(100)  # a value set at point 100: checkpoint 10 was taken before it, 12 after
    assert [checkpoint.serial for checkpoint in kept.kept] == [0, 4, 8, 10]
    assert kept.wanted(11)  # taken afresh as the run goes on, thinned as if 10 were the newest


@given(length=st.integers(min_value=1, max_value=5000))
def test_never_more_than_the_limit_are_kept_and_the_first_always(
    length: int,
) -> None:
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(module, "LIMIT", 10)
        kept = _run(range(length))
    assert len(kept) <= 10
    assert kept.kept[0].serial == 0
    assert kept.kept[-1].serial == length - 1


def _with_stretches(serials: range) -> Checkpoints:
    """Checkpoints whose stretch passed statement ``serial`` alone, each taken then thinned as a run goes."""
    kept = Checkpoints()
    for serial in serials:
        if kept.wanted(serial):
            checkpoint = _checkpoint(serial)
            checkpoint.passed.add(serial)
            kept.add(checkpoint)
    return kept


def test_a_checkpoint_thinned_out_hands_its_stretch_to_the_one_before() -> None:
    kept = _with_stretches(range(17))  # 0, 4, 8, 10, 12, 13, 14, 15, 16 kept (see above)
    assert {checkpoint.serial: checkpoint.passed for checkpoint in kept.kept} == {
        0: {0, 1, 2, 3},
        4: {4, 5, 6, 7},
        8: {8, 9},
        10: {10, 11},
        12: {12},
        13: {13},
        14: {14},
        15: {15},
        16: {16},
    }


def test_a_search_for_a_breakpoint_starts_at_the_latest_stretch_that_passed_its_statement() -> None:
    kept = _with_stretches(range(17))
    assert kept.search_from(165, frozenset({9})) == (kept.numbered(8), 100)  # 8's stretch ends at 10's (point 100)
    assert kept.search_from(165, frozenset({16})) == (kept.numbered(16), 165)
    assert kept.search_from(155, frozenset({16})) is None  # passed only after point 160
    assert kept.search_from(165, None) == (kept.numbered(16), 165)
    assert kept.search_from(160, None) == (kept.numbered(15), 160)


def test_the_limit_hands_the_stretches_it_drops_to_the_first() -> None:
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(module, "LIMIT", 3)
        kept = _with_stretches(range(6))  # 0..5 at one apart (ages 0-3), then 1, 3 dropped by thinning
    assert [checkpoint.serial for checkpoint in kept.kept] == [0, 4, 5]
    assert kept.kept[0].passed == {0, 1, 2, 3}
