""" "Replace v3 keywords" keeps each rename the v4 checker accepts, however many there are and wherever the
one it rejects stands (the renames are checked together, then in halves)."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from mintlang.lsp.features import migration
from mintlang.lsp.workspace import Analyses


@settings(max_examples=15, deadline=None)
@given(st.integers(min_value=0, max_value=12), st.integers(min_value=0, max_value=12))
def test_among_many_renames_only_the_one_the_checker_rejects_is_left_out(before, after):
    """#FASTPOS → #FASTIN would define #FASTIN twice (E3004); every HMSPEED → HOMESPEED around it is kept."""
    moves = [f"HMSPEED.0 = {n}" for n in range(before + after)]
    handlers = ["#FASTPOS", "RETURN", "#FASTIN", "RETURN"]
    text = "\n".join([*moves[:before], "END", *handlers[:2], *moves[before:], "RETURN", *handlers[2:]]) + "\n"
    snapshot = Analyses(read=lambda _: None).snapshot("file:///many.mnt", text, 1)
    kept = migration.checked(snapshot, {snapshot.unit: text}, migration.renames(snapshot))
    assert sorted(edit.text for fix in kept for edit in fix.edits) == ["HOMESPEED"] * (before + after)
