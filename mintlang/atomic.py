"""Rewriting a file so that each of its names holds, at every moment, either all of the old
bytes or all of the new ones: a reader, or a kill at any instant, never meets a mix.

``target`` decides before anything is written whether a file may be rewritten:
symbolic links are followed to the real file (the link stays a link), and
anything but a regular file the user may write is refused with a reason (a
device node such as /dev/null must never be replaced, and a read-only file is
protected even from root, who passes every permission check). So is a file
whose owner or group a new copy could not be given (only root gives files away)
and a file with a hard link outside its folder (that name could not be found, so
it would keep the old text).

``write`` puts the new bytes in a temporary file of the same folder
(``.NAME.XXXXXXXX.mint.tmp``, locked while in use), with the original's
permission bits, owner and group, flushed to disk; checks that the file still
holds the bytes the tool read (an edit saved meanwhile is not overwritten);
and renames the temporary file over the file's name, which replaces the name in
one step. A file with several hard links gets every name renamed onto the new
file, one after the other, so the links survive; a kill between two of those
renames leaves some names with the new text and the others with the old, each
complete. Last, the folder is flushed so that the renames survive a power cut.
A kill leaves the temporary file behind; mint-migrate's next run removes it.

``mint-migrate --write`` and ``mint check --fix`` write files this way.
"""

from __future__ import annotations

import contextlib
import fcntl
import os
import stat
from pathlib import Path

SUFFIX = ".mint.tmp"
_NAME_KEPT = 100  # characters of the file's name in a temporary name (names are at most 255)


class Unwritable(Exception):
    """A file that must not or cannot be rewritten; the message names it and says why."""


class Stale(Exception):
    """The file no longer holds what the tool read: an edit made since would be lost."""


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
    if not _can_give(status):
        raise Unwritable(f"cannot write {shown}: it belongs to another user or group, which a new copy could not keep")
    try:
        outside = status.st_nlink - len(names(real, status))
    except OSError as error:
        reason = f"its folder cannot be searched for its other names ({error.strerror or error})"
        raise Unwritable(f"cannot write {shown}: {reason}") from None
    if outside > 0:
        raise Unwritable(f"cannot write {shown}: it has hard links outside its folder, which would keep the old text")
    return real


def _can_give(status: os.stat_result) -> bool:
    """Whether a file this process creates can be given ``status``'s owner and group."""
    if os.geteuid() == 0:
        return True
    return status.st_uid == os.geteuid() and status.st_gid in {os.getegid(), *os.getgroups()}


def names(real: Path, status: os.stat_result) -> list[Path]:
    """The names of the file in its folder, ``real`` first (more only if it has hard links)."""
    found = [real]
    if status.st_nlink == 1:
        return found
    with os.scandir(real.parent) as listing:
        for entry in listing:
            if entry.name == real.name or entry.name.endswith(SUFFIX) or not entry.is_file(follow_symlinks=False):
                continue
            other = entry.stat(follow_symlinks=False)
            if (other.st_dev, other.st_ino) == (status.st_dev, status.st_ino):
                found.append(Path(entry.path))
    return found


def write(real: Path, data: bytes, expected: bytes) -> None:
    """Replace the contents of ``real`` (from ``target``) with ``data`` if it still holds
    ``expected`` (else raise ``Stale``), keeping its hard links, permission bits, owner and group."""
    status = real.stat()
    others = names(real, status)[1:]
    import tempfile  # noqa: PLC0415 - with shutil and random, only when a file is written

    handle, temporary = tempfile.mkstemp(dir=real.parent, prefix=f".{real.name[:_NAME_KEPT]}.", suffix=SUFFIX)
    links: list[str] = []
    try:
        fcntl.flock(handle, fcntl.LOCK_EX)  # held until closed: ``leftovers`` leaves a locked file alone
        _fill(handle, data, status)
        links = [_link(temporary, number) for number in range(1, len(others) + 1)]
        if _content(real) != expected:
            raise Stale(str(real))
        os.replace(temporary, real)
        for link, name in zip(links, others, strict=True):
            if _same_file(name, status):  # not replaced by someone else meanwhile
                os.replace(link, name)
        _flush_folder(real.parent)
    finally:
        for name in (temporary, *links):  # gone when renamed; left only when something failed
            with contextlib.suppress(OSError):
                os.unlink(name)
        os.close(handle)


def _fill(handle: int, data: bytes, status: os.stat_result) -> None:
    """The temporary file's bytes, mode, owner and group, flushed to disk."""
    with os.fdopen(os.dup(handle), "wb") as stream:
        stream.write(data)
    os.fchmod(handle, stat.S_IMODE(status.st_mode))
    copy = os.fstat(handle)
    if (copy.st_uid, copy.st_gid) != (status.st_uid, status.st_gid):
        os.fchown(handle, status.st_uid, status.st_gid)
    os.fsync(handle)


def _link(temporary: str, number: int) -> str:
    """A second temporary name for the new file, to rename over another hard link."""
    name = f"{temporary.removesuffix(SUFFIX)}-{number}{SUFFIX}"
    os.link(temporary, name)
    return name


def _content(real: Path) -> bytes | None:
    try:
        return real.read_bytes()
    except OSError:
        return None


def _same_file(name: Path, status: os.stat_result) -> bool:
    try:
        other = name.stat(follow_symlinks=False)
    except OSError:
        return False
    return (other.st_dev, other.st_ino) == (status.st_dev, status.st_ino)


def _flush_folder(folder: Path) -> None:
    """Make the renames durable; some file systems cannot flush a folder, and say so."""
    handle = os.open(folder, os.O_RDONLY | os.O_DIRECTORY)
    try:
        with contextlib.suppress(OSError):
            os.fsync(handle)
    finally:
        os.close(handle)
