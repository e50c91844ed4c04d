"""Semantic token deltas: only what changed since the client's last result, applied to give the whole."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st
from lsprotocol import types

from mintlang.lsp.features.semantic_tokens import difference
from tests.lsp.conftest import change, document, open_document, published, uri_of

_ints = st.lists(st.integers(0, 5), max_size=40)


def apply(data: list[int], edits: list[types.SemanticTokensEdit]) -> list[int]:
    result = list(data)
    for edit in sorted(edits, key=lambda edit: edit.start, reverse=True):
        result[edit.start : edit.start + edit.delete_count] = edit.data or []
    return result


@given(_ints, _ints)
def test_a_difference_applied_to_the_old_tokens_gives_the_new(old, new):
    edits = difference(old, new)
    assert apply(old, edits) == new
    assert (edits == []) == (old == new)


def common_ends(old: list[int], new: list[int]) -> tuple[int, int]:
    """The longest common beginning and end (not overlapping), an item at a time."""
    limit, prefix, suffix = min(len(old), len(new)), 0, 0
    while prefix < limit and old[prefix] == new[prefix]:
        prefix += 1
    while suffix < limit - prefix and old[-1 - suffix] == new[-1 - suffix]:
        suffix += 1
    return prefix, suffix


@given(st.binary(min_size=600, max_size=2000), st.integers(0, 2000), st.integers(0, 30), st.binary(max_size=30))
def test_a_difference_of_long_encodings_replaces_only_what_lies_between_their_common_ends(data, at, removed, inserted):
    """Long enough to be compared a block at a time; a few values only, so that blocks nearly match."""
    old = [byte % 4 for byte in data]
    new = old[:at] + [byte % 4 for byte in inserted] + old[at + removed :]
    edits = difference(old, new)
    assert apply(old, edits) == new
    if old != new:
        prefix, suffix = common_ends(old, new)
        (edit,) = edits
        assert (edit.start, edit.delete_count) == (prefix, len(old) - prefix - suffix)


def test_a_difference_keeps_the_common_beginning_and_end():
    (edit,) = difference([1, 2, 3, 4, 5], [1, 2, 9, 4, 5])
    assert (edit.start, edit.delete_count, edit.data) == (2, 1, [9])


@pytest.mark.asyncio
async def test_delta_after_an_edit(client, tmp_path):
    uri = uri_of(tmp_path / "delta.mnt")
    await open_document(client, uri, "DIM a\na = 1\nPRINT a\n")
    here = document(uri)
    first = await client.text_document_semantic_tokens_full_async(types.SemanticTokensParams(text_document=here))
    change(client, uri, 2, ((1, 4), (1, 5)), '"one"')  # a = "one": a number becomes a string
    await published(client, uri)
    answer = await client.text_document_semantic_tokens_full_delta_async(
        types.SemanticTokensDeltaParams(text_document=here, previous_result_id=first.result_id)
    )
    assert isinstance(answer, types.SemanticTokensDelta)
    assert answer.result_id not in (None, first.result_id)
    whole = await client.text_document_semantic_tokens_full_async(types.SemanticTokensParams(text_document=here))
    assert apply(list(first.data), list(answer.edits)) == list(whole.data)
    assert sum(len(edit.data or []) for edit in answer.edits) < len(whole.data)


@pytest.mark.asyncio
async def test_delta_from_an_unknown_result_is_the_whole(client, tmp_path):
    uri = uri_of(tmp_path / "unknown.mnt")
    await open_document(client, uri, "DIM a\nPRINT a\n")
    here = document(uri)
    answer = await client.text_document_semantic_tokens_full_delta_async(
        types.SemanticTokensDeltaParams(text_document=here, previous_result_id="stale")
    )
    whole = await client.text_document_semantic_tokens_full_async(types.SemanticTokensParams(text_document=here))
    assert isinstance(answer, types.SemanticTokens)
    assert list(answer.data) == list(whole.data)
