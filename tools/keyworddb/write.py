"""Serialise records to the committed JSON files, byte-for-byte reproducibly."""

from __future__ import annotations

import dataclasses
import json
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from mintlang.keyworddb.load import COMPACT, DOCUMENTS, compact, compacted


def to_json(value: Any) -> Any:
    """Plain JSON values: dataclasses become objects, tuples lists, enums their string."""
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return {field.name: to_json(getattr(value, field.name)) for field in dataclasses.fields(value)}
    if isinstance(value, Mapping):
        return {str(key): to_json(item) for key, item in value.items()}
    if isinstance(value, list | tuple):
        return [to_json(item) for item in value]
    return value


def render(value: Any) -> str:
    return json.dumps(to_json(value), indent=1, ensure_ascii=False, sort_keys=True) + "\n"


def differing(outputs: Mapping[str, Any], directory: Path) -> list[str]:
    """Names of the files whose committed text differs from ``outputs``, and the compact copy when it
    no longer holds every document as committed."""
    stale = [
        name
        for name, value in outputs.items()
        if not (directory / name).is_file() or (directory / name).read_text(encoding="utf-8") != render(value)
    ]
    return sorted(stale if compact_is_current(directory) else [*stale, COMPACT])


def write_all(outputs: Mapping[str, Any], directory: Path) -> None:
    directory.mkdir(parents=True, exist_ok=True)
    for name, value in outputs.items():
        (directory / name).write_text(render(value), encoding="utf-8")
    write_compact(directory)


def write_compact(directory: Path) -> None:
    """``database.bin``: the committed JSON documents marshalled, which the loader reads in their place."""
    (directory / COMPACT).write_bytes(compact(_texts(directory)))


def compact_is_current(directory: Path) -> bool:
    """Whether the loader takes every document from the compact copy, none from its JSON."""
    copy = directory / COMPACT
    texts = _texts(directory)
    return copy.is_file() and compacted(texts, copy.read_bytes()).keys() == texts.keys()


def _texts(directory: Path) -> dict[str, bytes]:
    """The JSON documents in ``directory``: the generator writes all but MintMT's, which are written by hand."""
    return {name: (directory / name).read_bytes() for name in DOCUMENTS if (directory / name).is_file()}
