"""The Debug Adapter Protocol's base framing: a JSON body after a ``Content-Length`` header, over byte streams.

The same framing as the Language Server Protocol, but DAP has no JSON-RPC
envelope and no maintained Python library outside debugpy (which debugs
Python itself): these few lines are the whole of it.
"""

from __future__ import annotations

import json
from typing import Any, BinaryIO

_LENGTH = b"content-length"
_CHUNK = 1 << 16  # a body is read this much at a time


class FramingError(Exception):
    """The peer sent something that is not a DAP message (no length, a bad length, a body that is not JSON)."""


def read_message(stream: BinaryIO) -> dict[str, Any] | None:
    """The next message, or None at the end of the stream; raises ``FramingError`` for a malformed one."""
    length: int | None = None
    while True:
        line = stream.readline()
        if not line:
            return None
        line = line.rstrip(b"\r\n")
        if not line:
            break
        name, _, value = line.partition(b":")
        if name.strip().lower() == _LENGTH:
            try:
                length = int(value.strip())
            except ValueError:
                raise FramingError(f"Content-Length is not a number: {value.strip()!r}") from None
            if length < 0:
                raise FramingError(f"Content-Length is not a length in bytes: {value.strip()!r}")
    if length is None:
        raise FramingError("a message without a Content-Length header")
    body = _body(stream, length)
    if body is None:
        return None
    try:
        message = json.loads(body)
    except (UnicodeDecodeError, json.JSONDecodeError) as error:
        raise FramingError(f"the message body is not JSON: {error}") from None
    except RecursionError:  # the decoder recurses once a level: [[[[...]]]] thousands deep
        raise FramingError("the message body is nested too deeply to read") from None
    if not isinstance(message, dict):
        raise FramingError("the message body is not a JSON object")
    return message


def _body(stream: BinaryIO, length: int) -> bytes | None:
    """``length`` bytes, read as they come (None if the stream ends first): one read of the whole length
    allocates it before any byte arrives, and a header claiming gigabytes was a MemoryError."""
    parts = []
    while length > 0:
        part = stream.read(min(length, _CHUNK))
        if not part:
            return None
        parts.append(part)
        length -= len(part)
    return b"".join(parts)


def write_message(stream: BinaryIO, message: dict[str, Any]) -> None:
    """Send one message, flushed at once (the client waits for it)."""
    body = json.dumps(message, ensure_ascii=False, separators=(",", ":")).encode("utf-8")
    stream.write(b"Content-Length: %d\r\n\r\n" % len(body))
    stream.write(body)
    stream.flush()
