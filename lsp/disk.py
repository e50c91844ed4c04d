"""The partner file on disk, read without going to the disk for every request.

Every request of a program's document needs its configuration file (and the
reverse). Reading and decoding it on every keystroke would make the editor as
slow as the disk: a network share on a machine's PC. A file's text is kept
while its size and modification time stay the same (a folder's names, to match
a name without regard to case, are kept by ``mintlang.pairing.names_in``).
"""

from __future__ import annotations

import logging
import stat
from pathlib import Path
from typing import TypeVar

from mintlang.source import read_source

T = TypeVar("T")

log = logging.getLogger(__name__)

_KEPT = 64  # files remembered

_texts: dict[Path, tuple[tuple[int, int], str]] = {}


def read_text(path: Path, max_bytes: int) -> str | None:
    """The decoded text of a regular file of at most ``max_bytes`` (cp1252 and latin-1 as ``mint check``
    reads them), or None."""
    try:
        status = path.stat()
    except OSError:
        return None
    if not stat.S_ISREG(status.st_mode) or status.st_size > max_bytes:
        return None
    stamp = (status.st_mtime_ns, status.st_size)
    kept = _texts.get(path)
    if kept is not None and kept[0] == stamp:
        return kept[1]
    try:
        text = read_source(path).text
    except OSError as error:
        log.warning("cannot read %s: %s", path, error)
        return None
    _remember(_texts, path, (stamp, text))
    return text


def _remember(cache: dict[Path, T], key: Path, value: T) -> None:
    if len(cache) >= _KEPT:
        cache.clear()
    cache[key] = value
