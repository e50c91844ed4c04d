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


def test_a_body_nested_too_deeply_to_read_is_a_parse_error() -> None:
    answers, log = _answers(b"[" * 100_000 + b"]" * 100_000)
    _, refused, shut_down = answers
    assert (refused["id"], refused["error"]["code"]) == (None, PARSE_ERROR)
    assert shut_down["id"] == 2
    assert "Traceback" not in log


def test_a_notification_with_params_that_do_not_fit_is_dropped_with_one_line_in_the_log() -> None:
    # nobody to answer (JSON-RPC); pygls logged a traceback and showed the user "Error in server: Invalid Params"
    opened = {"textDocument": {"uri": "file:///tmp/a.mnt", "languageId": "mint", "version": 1}}  # no text
    answers, log = _answers(_message(method="textDocument/didOpen", params=opened).split(b"\r\n\r\n", 1)[1])
    assert [answer.get("id") for answer in answers] == [1, 2]
    assert "dropped textDocument/didOpen: " in log
    assert "Traceback" not in log


def test_a_request_refused_on_purpose_is_answered_with_one_line_in_the_log() -> None:
    # pygls answered an unknown command with InvalidParams but logged the client's mistake with a traceback
    command = _message(id=3, method="workspace/executeCommand", params={"command": "nope", "arguments": []})
    answers, log = _answers(command.split(b"\r\n\r\n", 1)[1])
    refused = next(answer for answer in answers if answer.get("id") == 3)
    assert refused["error"]["code"] == -32602  # InvalidParams
    assert "refused request 3: Invalid Params: Command name 'nope' is not defined" in log
    assert "Traceback" not in log
