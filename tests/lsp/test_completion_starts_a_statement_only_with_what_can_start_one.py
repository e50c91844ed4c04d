"""Completion at a statement's start offers only the keywords ``mint check`` takes there: a parameter that is
only read is no statement (error 2000 given a value, 2005 alone), though the guide prints it no attributes table:
ERL, ERR, ERRAXIS and INKEY, whose every format reads them (000:9881, 9901, 9943, 12145)."""

from __future__ import annotations

import pytest
from lsprotocol import types

from mintlang.lsp.features.completion import complete
from mintlang.lsp.workspace import Analyses, Settings


def _offered(text: str) -> set[str]:
    analyses = Analyses(read=lambda _: None, settings=Settings.from_options({"controller": "nextmove-bx"}))
    snapshot = analyses.snapshot("file:///start.mnt", text, 1)
    line = text.count("\n")
    prefix = text.rsplit("\n", 1)[-1]
    return {item.label for item in complete(snapshot, prefix, types.Position(line=line, character=len(prefix)))}


@pytest.mark.parametrize("word", ["ERL", "ERR", "ERRAXIS", "INKEY"])
def test_a_keyword_only_read_does_not_start_a_statement(word: str) -> None:
    assert word not in _offered("DIM a\n")


@pytest.mark.parametrize("word", ["ERL", "ERR", "ERRAXIS", "INKEY"])
def test_it_is_offered_where_a_value_is_read(word: str) -> None:
    assert word in _offered("DIM a\na = ")


@pytest.mark.parametrize("word", ["SPEED", "GO", "DRIVEENABLE"])
def test_a_keyword_given_a_value_or_a_command_starts_one(word: str) -> None:
    assert word in _offered("DIM a\n")
