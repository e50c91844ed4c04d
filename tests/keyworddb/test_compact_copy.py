"""The keyword database is read from ``database.bin``, its JSON documents marshalled, only where
that copy was made from the JSON as it is: an edited JSON file is read itself, never stale."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from mintlang.keyworddb import load
from tools.keyworddb.write import compact_is_current

DATA = Path(load.__file__).parent / "data"


def _texts() -> dict[str, bytes]:
    return {name: (DATA / name).read_bytes() for name in load.DOCUMENTS}


def _edited_speed() -> bytes:
    keywords = json.loads(_texts()["keywords_v4.json"])
    next(raw for raw in keywords if raw["name"] == "SPEED")["summary"] = "Edited by hand."
    return json.dumps(keywords).encode("utf-8")


def test_the_shipped_copy_holds_every_document_as_committed() -> None:
    assert compact_is_current(DATA), "run: python -m tools.keyworddb --compact"
    assert load.documents() == {name: json.loads(text) for name, text in _texts().items()}


def test_a_document_edited_after_the_copy_was_made_is_read_from_its_json(monkeypatch: pytest.MonkeyPatch) -> None:
    shipped = load.read_bytes
    edited = _edited_speed()
    monkeypatch.setattr(
        load,
        "read_bytes",
        lambda package, *parts: edited if parts[-1] == "keywords_v4.json" else shipped(package, *parts),
    )
    read = load.documents()
    assert next(raw for raw in read["keywords_v4.json"] if raw["name"] == "SPEED")["summary"] == "Edited by hand."
    assert load.compacted({**_texts(), "keywords_v4.json": edited}, (DATA / load.COMPACT).read_bytes()).keys() == (
        set(load.DOCUMENTS) - {"keywords_v4.json"}
    )


@pytest.mark.parametrize("copy", [b"", b"not marshal data", b"\x00" * 16, b"i\x07\x00\x00\x00"])
def test_a_copy_that_cannot_be_read_keeps_no_document(copy: bytes) -> None:
    assert load.compacted(_texts(), copy) == {}


def test_without_a_copy_every_document_is_read_from_its_json(monkeypatch: pytest.MonkeyPatch) -> None:
    shipped = load.read_bytes

    def without_copy(package: str, *parts: str) -> bytes:
        if parts[-1] == load.COMPACT:
            raise FileNotFoundError(parts[-1])
        return shipped(package, *parts)

    monkeypatch.setattr(load, "read_bytes", without_copy)
    assert load.documents() == {name: json.loads(text) for name, text in _texts().items()}
