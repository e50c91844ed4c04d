"""Rewriting a file in place without ever leaving it half-written or breaking what points at it.

``target`` decides before anything is written whether a file may be rewritten:
symbolic links are followed to the real file (the link stays a link), and
anything but a regular file the user may write is refused with a reason (a
device node such as /dev/null must never be replaced, and a read-only file is
protected even from root, who passes every permission check).

``write`` then puts the new bytes in a temporary file of the same directory and
renames it over the original: readers see the old file or the new one, never a
mix, and a failure leaves the original untouched. A rename would give a file
with several hard links a new inode (the other names keeping the old text), or
a new owner when it cannot be given back; such a file is overwritten in place
instead, after a backup copy is made beside it, which restores it if the write
fails and survives if the process is killed.
"""

from __future__ import annotations

import contextlib
import os
import shutil
import stat
import tempfile
from pathlib import Path
from typing import BinaryIO


class Unwritable(Exception):
    """A file ``--write`` must not or cannot rewrite; the message names it and says why."""


def target(path: Path) -> Path:
    """The real file behind ``path`` (symbolic links followed), if it may be rewritten."""
    try:
        real = path.resolve(strict=True)
        status = real.stat()
    except OSError as error:
        raise Unwritable(f"cannot write {path}: {error.strerror or error}") from None
    shown = f"{path} (link to {real})" if path.is_symlink() else str(path)
    if not stat.S_ISREG(status.st_mode):
        raise Unwritable(f"cannot write {shown}: not a regular file")
    if not status.st_mode & 0o222 or not os.access(real, os.W_OK):
        raise Unwritable(f"cannot write {shown}: the file is read-only")
    if not os.access(real.parent, os.W_OK | os.X_OK):
        raise Unwritable(f"cannot write {shown}: its directory {real.parent} is not writable")
    return real


def write(real: Path, data: bytes) -> None:
    """Replace the contents of the regular file ``real`` (from ``target``) with ``data``,
    keeping its inode when it has several hard links, and its permission bits, owner and group."""
    status = real.stat()
    if status.st_nlink > 1 or not _replace(real, data, status):
        _overwrite(real, data)


def _temporary(real: Path, suffix: str) -> tuple[int, str]:
    return tempfile.mkstemp(dir=real.parent, prefix=f".{real.name}.", suffix=suffix)


def _replace(real: Path, data: bytes, status: os.stat_result) -> bool:
    """Write ``data`` beside ``real`` and rename it over; False (nothing changed) when the copy
    could not be given the original's owner and group."""
    handle, temporary = _temporary(real, ".tmp")
    try:
        with os.fdopen(handle, "wb") as stream:
            stream.write(data)
            stream.flush()
            os.fsync(stream.fileno())
        os.chmod(temporary, stat.S_IMODE(status.st_mode))
        copy = os.stat(temporary)
        if (copy.st_uid, copy.st_gid) != (status.st_uid, status.st_gid):
            try:
                os.chown(temporary, status.st_uid, status.st_gid)
            except PermissionError:
                os.unlink(temporary)
                return False
        os.replace(temporary, real)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(temporary)
        raise
    return True


def _overwrite(real: Path, data: bytes) -> None:
    handle, backup = _temporary(real, ".bak")
    os.close(handle)
    try:
        shutil.copyfile(real, backup)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(backup)
        raise
    try:
        with real.open("r+b") as stream:
            _fill(stream, data)
    except BaseException:
        with real.open("r+b") as stream, open(backup, "rb") as original:
            _fill(stream, original.read())
        os.unlink(backup)  # kept, with the original, if even the restore failed
        raise
    os.unlink(backup)


def _fill(stream: BinaryIO, data: bytes) -> None:
    stream.seek(0)
    stream.write(data)
    stream.truncate()
    stream.flush()
    os.fsync(stream.fileno())
