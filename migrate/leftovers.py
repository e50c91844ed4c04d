"""Temporary files a killed ``--write`` left in the user's folders.

A kill between writing the temporary file and renaming it leaves
``.NAME.XXXXXXXX.mint.tmp`` beside the file it was for (see ``mintlang.atomic``).
Every run looks for them in the folders of the files it reads: ``--write`` removes
them, the other modes (which write nothing) only name them. A temporary file that
a running ``mint-migrate`` still holds is locked, and is left alone.
"""

from __future__ import annotations

import contextlib
import fcntl
import os
from collections.abc import Iterable
from pathlib import Path

from mintlang.atomic import SUFFIX


def find(folders: Iterable[Path]) -> list[Path]:
    """The temporary files of interrupted writes in ``folders``, sorted; none that is in use."""
    found: list[Path] = []
    for folder in sorted(set(folders)):
        with contextlib.suppress(OSError), os.scandir(folder) as listing:
            found.extend(
                Path(entry.path)
                for entry in listing
                if entry.name.startswith(".") and entry.name.endswith(SUFFIX) and entry.is_file(follow_symlinks=False)
            )
    return sorted(path for path in found if not _in_use(path))


def _in_use(path: Path) -> bool:
    try:
        handle = os.open(path, os.O_RDONLY | os.O_NOFOLLOW)
    except OSError:
        return True  # gone, or not ours to judge
    try:
        fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        return True
    finally:
        os.close(handle)
    return False


def remove(paths: Iterable[Path]) -> list[str]:
    """Remove each leftover; one line per file saying what happened."""
    said = []
    for path in paths:
        try:
            path.unlink()
        except OSError as error:
            said.append(f"cannot remove {path}, left by an interrupted --write: {error.strerror or error}")
        else:
            said.append(f"removed {path}, left by an interrupted --write")
    return said


def named(paths: Iterable[Path]) -> list[str]:
    """What a run that writes nothing says about each leftover."""
    return [f"{path} was left by an interrupted --write, which removes it" for path in paths]
