"""Params a request cannot be decoded with are the client's mistake: the server's log says so in one line,
with what was wrong, and no traceback (the request itself is answered with ``InvalidParams``)."""

from __future__ import annotations

import logging
from typing import Any

import pytest

from mintlang.lsp.server import MintServer

HERE = {"uri": "file:///tmp/a.mnt"}


@pytest.mark.parametrize(
    ("params", "said"),
    [
        pytest.param(
            {"textDocument": HERE, "position": {"line": -1, "character": 0}},
            "ValueError: Position.line should be in range [0:2147483647], but was -1.",
            id="a negative position",
        ),
        pytest.param({"textDocument": HERE}, "KeyError: 'position'", id="no position"),
    ],
)
def test_undecodable_params_are_logged_in_one_line(
    caplog: pytest.LogCaptureFixture, params: dict[str, Any], said: str
) -> None:
    server = MintServer()
    answers: list[Any] = []
    server.protocol._send_response = lambda *arguments, **keywords: answers.append(keywords["error"].code)  # type: ignore[method-assign]
    message = {"jsonrpc": "2.0", "id": 1, "method": "textDocument/hover", "params": params}
    with caplog.at_level(logging.ERROR, logger="pygls.protocol.json_rpc"):
        server.protocol.structure_message(message)
    assert answers == [-32602]  # InvalidParams
    logged = [record.getMessage() for record in caplog.records if record.name == "pygls.protocol.json_rpc"]
    assert logged == [f"undecodable message: {said}"]
