"""DAP's ``noDebug`` launch (VS Code's Run Without Debugging, Ctrl+F5, which keeps the configuration's
``stopOnEntry``): the program runs to its end, past its breakpoints and its errors."""

from __future__ import annotations

from pathlib import Path

from tests.debugger.client import DapClient
from tests.debugger.conftest import Debug

FAILING = """\
DIM i
FOR i = 1 TO 3
  PRINT i
NEXT
PRINT 10 / (i - 3)
"""


def test_a_run_without_debugging_stops_at_no_entry_breakpoint_or_error(tmp_path: Path) -> None:
    # the loop leaves i at 3, its last value (NM-9), so line 5 divides by zero: error 2021 (000:19063)
    program = tmp_path / "failing.mnt"
    program.write_text(FAILING, encoding="utf-8")
    client = DapClient()
    try:
        client.program = program
        client.body("initialize", {"adapterID": "mint"})
        client.body("launch", {"program": str(program), "stopOnEntry": True, "noDebug": True})
        client.event("initialized")
        client.set_breakpoints(3, {"line": 4, "condition": "i = 2"})
        client.body("setFunctionBreakpoints", {"breakpoints": [{"name": "ONERROR"}]})
        client.body("setExceptionBreakpoints", {"filters": ["errors", "unhandled"]})
        client.body("configurationDone")
        assert client.event("exited")["body"]["exitCode"] == 1
        client.event("terminated")
        assert not [event for event in client.events if event["event"] == "stopped"]
        assert client.output().startswith("1\n2\n3\n")
    finally:
        client.close()


def test_its_breakpoints_are_unverified_and_say_why(debug: Debug) -> None:
    client = debug("PAUSE TIME >= 60000\n", noDebug=True)
    for placed in [
        *client.set_breakpoints(1),
        *client.body("setFunctionBreakpoints", {"breakpoints": [{"name": "TIMER"}]})["breakpoints"],
    ]:
        assert not placed["verified"]
        assert "without debugging" in placed["message"]
