"""A body that is not JSON, or JSON that is no message, is answered as JSON-RPC says, with a null id.

pygls logged such a body with a traceback, showed the user a server error and answered nothing.
"""

from __future__ import annotations

import json
import subprocess
import sys
from typing import Any

PARSE_ERROR, INVALID_REQUEST = -32700, -32600


def _framed(body: bytes) -> bytes:
    return b"Content-Length: %d\r\n\r\n" % len(body) + body


def _message(**fields: Any) -> bytes:
    return _framed(json.dumps({"jsonrpc": "2.0", **fields}).encode("utf-8"))


def _answers(*bodies: bytes) -> tuple[list[dict[str, Any]], str]:
    """What the server writes back to ``initialize``, the bodies, ``shutdown`` and ``exit``; and its log."""
    session = b"".join(
        (
            _message(id=1, method="initialize", params={"capabilities": {}}),
            *map(_framed, bodies),
            _message(id=2, method="shutdown"),
            _message(method="exit"),
        )
    )
    done = subprocess.run(
        [sys.executable, "-m", "mintlang.lsp"], input=session, capture_output=True, timeout=120, check=False
    )
    parts = done.stdout.split(b"Content-Length: ")[1:]
    return [json.loads(part.split(b"\r\n\r\n", 1)[1]) for part in parts], done.stderr.decode()


def test_what_cannot_be_read_is_answered_and_the_server_goes_on() -> None:
    answers, log = _answers(b"{bad}", b"[]", b"5", b"\xff\xfe")
    initialized, *refused, shut_down = answers
    assert initialized["id"] == 1 and "capabilities" in initialized["result"]
    assert [(answer["id"], answer["error"]["code"]) for answer in refused] == [
        (None, PARSE_ERROR),
        (None, INVALID_REQUEST),
        (None, INVALID_REQUEST),
        (None, PARSE_ERROR),
    ]
    assert shut_down == {"jsonrpc": "2.0", "id": 2, "result": None}
    assert "Traceback" not in log
