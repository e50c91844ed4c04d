"""The lexer's spellings of a keyword are read from its entry without building its record; they say
what the record says, and a keyword's record is built once, when first asked for."""

from __future__ import annotations

import pytest

from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Controller, Keyword, Spelling


def _spelling_of(keyword: Keyword) -> Spelling:
    return Spelling(
        keyword.name,
        keyword.abbreviations,
        keyword.kind,
        bool(keyword.parameters),
        keyword.channel_suffix,
        len(keyword.indices),
    )


@pytest.mark.parametrize("dialect", [Dialect.V4, Dialect.MINTMT])
def test_every_spelling_says_what_the_keyword_record_says(dialect: Dialect) -> None:
    db = database()
    assert db.spellings_of(dialect) == [_spelling_of(keyword) for keyword in db.keywords_of(dialect).values()]


@pytest.mark.parametrize(
    ("word", "controller", "name"),
    [
        ("hp", Controller.MINTDRIVE, "HANDLERPENDING"),  # HP is given to both; only the MintDrive has HANDLERPENDING
        ("HP", Controller.NEXTMOVE_PCI, "HOMEPOS"),  # and only the NextMove HOMEPOS
        ("spd", None, "SPEEDDEMAND"),
        ("In3", None, "IN"),  # a channel glued to a keyword that takes one
        ("SPEEDX", None, None),
    ],
)
def test_the_owner_of_a_spelling_is_the_name_of_the_keyword_lookup_finds(
    word: str, controller: Controller | None, name: str | None
) -> None:
    db = database()
    assert db.owner(word, controller) == name
    found = db.lookup(word, controller)
    assert (found.name if found is not None else None) == name


def test_a_keyword_record_is_built_once() -> None:
    db = database()
    assert db.keywords["SPEED"] is db.keywords["SPEED"] is db.lookup("speed")
    assert db.keywords.get("SPEED") is db.keywords["SPEED"]
    assert db.keywords.get("NO_SUCH_KEYWORD") is None
    assert "SPEED" in db.keywords
    assert "NO_SUCH_KEYWORD" not in db.keywords
