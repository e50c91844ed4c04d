"""The unified diff ``mint check --diff``, ``mint format --diff`` and ``mint-migrate`` print, one that ``patch``
applies."""

from __future__ import annotations

import re
from typing import IO

from mintlang.diagnostics import split_lines

_AS_TEXT = ("utf-8", "utf-8-sig")  # what the stream writes anyway (a mark stays out of the diff's middle)
_LONE_CR = re.compile(r"\r(?!\n)")


def unified(before: str, after: str, fromfile: str, tofile: str) -> str:
    """``diff -u`` of two texts, as ``patch`` applies it: a line keeps its CRLF, and a last line without a
    line end is marked so. Lines end only where Mint's do (``split_lines``), and each keeps its own end, a
    lone CR too, as ruff's diff and ``difflib`` keep it: the diff shows the line ends the change writes.
    (``patch`` does not take a lone CR for a line end: such a file is one line to it.)"""
    import difflib  # noqa: PLC0415 - imported for a diff alone

    lines = difflib.unified_diff(
        split_lines(before, keepends=True), split_lines(after, keepends=True), fromfile=fromfile, tofile=tofile
    )
    return "".join(_ended(line) for line in lines)


def _ended(line: str) -> str:
    if line.endswith(("\n", "\r")):
        return line
    return f"{line}\n\\ No newline at end of file\n"


def write_diff(stream: IO[str], diff: str, encoding: str) -> None:
    """``diff`` of a file read in ``encoding``, written to ``stream``. For ``patch`` (a file, a pipe) it goes in
    that encoding: patch matches bytes, and a cp1252 program's diff written in UTF-8 does not apply to it. On a
    terminal it is text, to be read: a line break follows a lone CR, which would have the next line written
    over its line."""
    if stream.isatty():
        stream.write(_LONE_CR.sub("\r\n", diff))
        return
    buffer = getattr(stream, "buffer", None)
    if buffer is None or encoding in _AS_TEXT:
        stream.write(diff)
        return
    stream.flush()
    buffer.write(diff.encode(encoding, errors="replace"))  # only a file name can hold what the encoding lacks
    buffer.flush()
