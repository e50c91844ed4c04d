"""Run in simulator: a code lens on every program, and the server command it runs.

The lens runs ``mint.simulateFile`` on the server (VS Code's language client
turns server commands into editor commands; other clients send
``workspace/executeCommand``). The program and its paired configuration file
run in ``mint-run``'s simulator on a worker thread, bounded in simulated and
real time, so the server keeps answering meanwhile. What the program printed
goes to the client's log, a one-line outcome is shown, and the command answers
with the same JSON report as ``mint-run --report json``.
"""

from __future__ import annotations

import asyncio
from typing import Any

from lsprotocol import types

from mintlang.dialect import Dialect
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import partner
from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.report import as_json
from mintlang.runtime.run import RunResult, run_source
from mintlang.runtime.scenario import ScenarioFileError
from mintlang.runtime.simulation import Limits
from mintlang.semantic.units import Unit

SIMULATE = "mint.simulateFile"
TITLE = "▶ Run in simulator"
LIMITS = Limits(until_ms=600_000, max_wall_s=20.0)  # ten simulated minutes, at most 20 s of the user's time


def lenses(server: MintServer, uri: str) -> list[types.CodeLens]:
    """One lens on the first line of a Mint v4 program (configuration files run with their program); the
    code lens method is ``reference_lenses``', which shows this lens with the reference counts."""
    snapshot = server.snapshot(uri)
    if snapshot is None or snapshot.unit is Unit.CONFIGURATION or snapshot.skipped:
        return []
    if snapshot.settings.dialect is not Dialect.V4:
        return []
    start = types.Position(line=0, character=0)
    command = types.Command(title=TITLE, command=SIMULATE, arguments=[uri])
    return [types.CodeLens(range=types.Range(start=start, end=start), command=command)]


def summary(result: RunResult) -> str:
    stop = result.stop
    where = f" at line {stop.line} ({stop.statement})" if stop.line is not None else ""
    why = f": {stop.message}" if stop.message else ""
    return f"Simulation {stop.reason.value} after {stop.time_ms} ms{where}{why}"


def register(server: MintServer) -> None:
    @server.command(SIMULATE)
    async def simulate(ls: MintServer, uri: str) -> dict[str, Any] | None:
        settings = ls.analyses.settings_for(uri)
        unit, other = partner(uri, settings, ls.opened())
        # asked for a configuration file, run the program it configures
        program_uri, configuration_uri = (other, uri) if unit is Unit.CONFIGURATION and other else (uri, other)
        source = ls.read_text(program_uri)
        if source is None:
            ls.window_show_message(
                types.ShowMessageParams(
                    type=types.MessageType.Error, message=f"Cannot read {program_uri} to simulate it"
                )
            )
            return None
        configuration = ls.read_text(configuration_uri) if configuration_uri is not None else None
        try:
            result = await asyncio.to_thread(
                run_source, source, config=configuration, controller=settings.controller, limits=LIMITS
            )
        except ScenarioFileError as error:
            ls.window_show_message(types.ShowMessageParams(type=types.MessageType.Error, message=str(error)))
            return None
        if result.terminal:
            ls.window_log_message(types.LogMessageParams(type=types.MessageType.Log, message=result.terminal))
        normal = result.stop.reason in (StopReason.END, StopReason.UNTIL)
        kind = types.MessageType.Info if normal else types.MessageType.Error
        ls.window_show_message(types.ShowMessageParams(type=kind, message=summary(result)))
        return as_json(result)
