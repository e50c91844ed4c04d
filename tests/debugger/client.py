"""A small DAP client for the tests: ``mint-dap`` in a subprocess, spoken to over its real stdin and stdout.

Every message the adapter sends is checked against the protocol's schema as it
arrives; ``DapClient.close`` fails the test if one did not conform.
"""

from __future__ import annotations

import contextlib
import queue
import subprocess
import sys
import threading
from pathlib import Path
from typing import Any

from mintlang.runtime.debugger.framing import read_message, write_message
from tests.debugger.schema import problems

TIMEOUT_S = 30.0


def adapter_command() -> list[str]:
    """The installed ``mint-dap`` script, beside the interpreter running the tests."""
    script = Path(sys.executable).with_name("mint-dap")
    return (
        [str(script)]
        if script.exists()
        else [sys.executable, "-c", "from mintlang.runtime.debugger.cli import main; main()"]
    )


class DapClient:
    def __init__(self, *arguments: str) -> None:
        self.process = subprocess.Popen(
            [*adapter_command(), *arguments], stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE
        )
        self.sequence = 0
        self.messages: queue.Queue[dict[str, Any]] = queue.Queue()
        self.events: list[dict[str, Any]] = []  # every event, in order
        self.nonconforming: list[str] = []
        self.program = Path()  # the program launched, once it is
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self) -> None:
        assert self.process.stdout is not None
        while (message := read_message(self.process.stdout)) is not None:
            self.nonconforming.extend(problems(message))
            self.messages.put(message)

    def send(self, command: str, arguments: dict[str, Any] | None = None) -> int:
        assert self.process.stdin is not None
        self.sequence += 1
        request: dict[str, Any] = {"seq": self.sequence, "type": "request", "command": command}
        if arguments is not None:
            request["arguments"] = arguments
        write_message(self.process.stdin, request)
        return self.sequence

    def request(self, command: str, arguments: dict[str, Any] | None = None) -> dict[str, Any]:
        """The response to ``command`` (success or not); events that come first are kept in ``events``."""
        sequence = self.send(command, arguments)
        while True:
            message = self._next()
            if message["type"] == "response" and message["request_seq"] == sequence:
                return message

    def body(self, command: str, arguments: dict[str, Any] | None = None) -> dict[str, Any]:
        """The body of a response that must succeed."""
        response = self.request(command, arguments)
        assert response["success"], response.get("message")
        return response.get("body", {})

    def event(self, name: str) -> dict[str, Any]:
        """The next event called ``name`` not yet taken."""
        return self.event_of(name)

    def event_of(self, *names: str) -> dict[str, Any]:
        """The next event called one of ``names`` not yet taken."""
        for index, event in enumerate(self.events):
            if event["event"] in names:
                return self.events.pop(index)
        while True:
            message = self._next()
            if message["type"] == "event" and message["event"] in names:
                self.events.remove(message)
                return message

    def _next(self) -> dict[str, Any]:
        try:
            message = self.messages.get(timeout=TIMEOUT_S)
        except queue.Empty:
            raise AssertionError(f"mint-dap sent nothing for {TIMEOUT_S} s") from None
        if message["type"] == "event":
            self.events.append(message)
        return message

    # ------------------------------------------------------------ shorthands

    def stopped(self) -> dict[str, Any]:
        """The body of the next ``stopped`` event."""
        return self.event("stopped")["body"]

    def line(self) -> int:
        """The line the paused program stands at (its innermost frame)."""
        return self.frames()[0]["line"]

    def frames(self) -> list[dict[str, Any]]:
        return self.body("stackTrace", {"threadId": 1})["stackFrames"]

    def scope(self, name: str) -> int:
        scopes = self.body("scopes", {"frameId": 1})["scopes"]
        return next(scope["variablesReference"] for scope in scopes if scope["name"] == name)

    def variables(self, reference: int, **paging: int) -> dict[str, str]:
        listed = self.body("variables", {"variablesReference": reference, **paging})["variables"]
        return {variable["name"]: variable["value"] for variable in listed}

    def values(self) -> dict[str, str]:
        """The program's variables, by name, as the editor shows them."""
        return self.variables(self.scope("Variables"))

    def evaluate(self, expression: str) -> str:
        return self.body("evaluate", {"expression": expression, "context": "watch", "frameId": 1})["result"]

    def step(self, command: str) -> dict[str, Any]:
        """Send a stepping command (next, stepIn, stepBack …) and wait for the stop it leads to."""
        self.body(command, {"threadId": 1})
        return self.stopped()

    def set_breakpoints(self, *breakpoints: int | dict[str, Any]) -> list[dict[str, Any]]:
        wanted = [{"line": item} if isinstance(item, int) else item for item in breakpoints]
        arguments = {"source": {"path": str(self.program)}, "breakpoints": wanted}
        return self.body("setBreakpoints", arguments)["breakpoints"]

    def outputs(self) -> list[dict[str, Any]]:
        """The bodies of the output events received so far."""
        return [event["body"] for event in self.events if event["event"] == "output"]

    def output(self) -> str:
        """What the program printed, from the output events received so far."""
        return "".join(body["output"] for body in self.outputs() if body.get("category") == "stdout")

    def close(self) -> str:
        """End the session; the adapter's stderr. Fails if a message did not conform to the schema."""
        if self.process.poll() is None:
            with contextlib.suppress(AssertionError, BrokenPipeError):
                self.request("disconnect", {"terminateDebuggee": True})
        try:
            _, stderr = self.process.communicate(timeout=TIMEOUT_S)
        except subprocess.TimeoutExpired:
            self.process.kill()
            _, stderr = self.process.communicate()
        assert not self.nonconforming, self.nonconforming
        return stderr.decode("utf-8", "replace")
