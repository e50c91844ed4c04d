"""Reading and writing Mint source files byte-exactly.

Old Windows tools saved programs in cp1252 or latin-1. A file is decoded as
UTF-8 when it is valid UTF-8, else as cp1252, else as latin-1 (which maps
every byte); encoding the text again with the same codec gives back the same
bytes, so tools that rewrite a file never change what they did not mean to. A
UTF-8 byte order mark is read as part of the encoding (``utf-8-sig``), not of the
text: no editor shows it, so columns on line 1 count from the first character
shown, and writing the file back puts the mark back.
"""

from __future__ import annotations

import errno
import stat
import sys
from codecs import BOM_UTF8, BOM_UTF16_BE, BOM_UTF16_LE
from pathlib import Path

from mintlang.diagnostics import LineIndex, Position
from mintlang.records import record

_ENCODINGS = ("utf-8", "cp1252", "latin-1")
NOT_TEXT = "not Mint text (a NUL byte)"  # why a file with a NUL byte is not read as a program
_MARKED = ("utf-8-sig", *_ENCODINGS)  # utf-8-sig drops the mark when it decodes and writes it when it encodes


@record
class SourceFile:
    path: Path
    text: str
    encoding: str

    def encode(self, text: str | None = None) -> bytes:
        """``text`` (default: the file's own) in the file's encoding."""
        return (self.text if text is None else text).encode(self.encoding)

    def binary(self) -> str | None:
        """Why the file is not Mint text, with where (``path:line:column``), or None."""
        position = self.nul()
        if position is None:
            return None
        return f"{self.path}:{position.line}:{position.column}: {self.not_text()}"

    def not_text(self) -> str:
        """Why a file with a NUL byte is not read. Windows editors save "Unicode" as UTF-16, a NUL byte after
        each ASCII character: its author is told what to save it as, not only that it is binary."""
        return f"{NOT_TEXT}: UTF-16 text; save it as UTF-8" if self._utf16() else NOT_TEXT

    def _utf16(self) -> bool:
        data = self.encode()
        if not data.startswith((BOM_UTF16_LE, BOM_UTF16_BE)):
            return False
        try:
            data.decode("utf-16")  # the mark says which byte order
        except UnicodeDecodeError:  # binary data that happens to start so (an odd length, a lone surrogate)
            return False
        return True

    def nul(self) -> Position | None:
        """Where the first NUL byte is, or None.

        A NUL byte never occurs in a program; a tool that read on would answer a
        binary file with hundreds of syntax errors, or scatter REM lines through it.
        """
        offset = self.text.find("\0")
        return None if offset < 0 else LineIndex(self.text).position(offset)


def decode(data: bytes) -> tuple[str, str]:
    """The text of ``data`` and the encoding that reproduces ``data`` exactly."""
    for encoding in _MARKED if data.startswith(BOM_UTF8) else _ENCODINGS:
        try:
            text = data.decode(encoding)
        except UnicodeDecodeError:
            continue
        if text.encode(encoding) == data:
            return text, encoding
    raise AssertionError("latin-1 decodes every byte string")  # pragma: no cover


def read_regular(path: Path) -> bytes:
    """The bytes of a file; raises OSError when it cannot be read or is not a regular file.

    A pipe would block a tool forever and a device such as /dev/zero never ends.
    """
    if not stat.S_ISREG(path.stat().st_mode):
        raise OSError(errno.EINVAL, "not a regular file", str(path))
    return path.read_bytes()


def read_stdin(name: str | None) -> SourceFile:
    """Standard input as a source file, named ``name`` (an editor's ``--stdin-filename``) or ``-``."""
    text, encoding = decode(sys.stdin.buffer.read())
    return SourceFile(Path(name or "-"), text, encoding)


def read_source(path: Path) -> SourceFile:
    """Read a source file; raises OSError when it cannot be read or is not a regular file."""
    text, encoding = decode(read_regular(path))
    return SourceFile(path, text, encoding)
