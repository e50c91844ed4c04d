"""The Debug Adapter Protocol's base framing: a JSON body after a ``Content-Length`` header, over byte streams.

The same framing as the Language Server Protocol, but DAP has no JSON-RPC
envelope and no maintained Python library outside debugpy (which debugs
Python itself): these twenty lines are the whole of it.
"""

from __future__ import annotations

import json
from typing import Any, BinaryIO

_LENGTH = b"content-length"


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
    if length is None or length < 0:
        raise FramingError("a message without a Content-Length header")
    body = stream.read(length)
    if len(body) < length:
        return None
    try:
        message = json.loads(body)
    except (UnicodeDecodeError, json.JSONDecodeError) as error:
        raise FramingError(f"the message body is not JSON: {error}") from None
    if not isinstance(message, dict):
        raise FramingError("the message body is not a JSON object")
    return message


def write_message(stream: BinaryIO, message: dict[str, Any]) -> None:
    """Send one message, flushed at once (the client waits for it)."""
    body = json.dumps(message, ensure_ascii=False, separators=(",", ":")).encode("utf-8")
    stream.write(b"Content-Length: %d\r\n\r\n" % len(body))
    stream.write(body)
    stream.flush()
