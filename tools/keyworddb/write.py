"""Serialise records to the committed JSON files, byte-for-byte reproducibly."""

from __future__ import annotations

import dataclasses
import json
from collections.abc import Mapping
from pathlib import Path
from typing import Any


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
    """Names of the files whose committed text differs from ``outputs``."""
    return sorted(
        name
        for name, value in outputs.items()
        if not (directory / name).is_file() or (directory / name).read_text(encoding="utf-8") != render(value)
    )


def write_all(outputs: Mapping[str, Any], directory: Path) -> None:
    directory.mkdir(parents=True, exist_ok=True)
    for name, value in outputs.items():
        (directory / name).write_text(render(value), encoding="utf-8")
