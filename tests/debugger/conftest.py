"""A debugging session on a program written for the test, closed (and its messages checked) at teardown."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

from tests.debugger.client import DapClient

Debug = Callable[..., DapClient]


@pytest.fixture
def debug(tmp_path: Path) -> Iterator[Debug]:
    """``debug(source, breakpoints=[lines or dicts], **launch)``: a session launched on ``source`` and configured."""
    clients: list[DapClient] = []

    def start(source: str, *, breakpoints: tuple[Any, ...] = (), name: str = "program.mnt", **launch: Any) -> DapClient:
        program = tmp_path / name
        program.write_text(source, encoding="utf-8")
        client = DapClient()
        clients.append(client)
        client.program = program
        client.body("initialize", {"adapterID": "mint", "linesStartAt1": True, "columnsStartAt1": True})
        client.body("launch", {"program": str(program), **launch})
        client.event("initialized")
        if breakpoints:
            client.set_breakpoints(*breakpoints)
        client.body("configurationDone")
        return client

    yield start
    for client in clients:
        client.close()
