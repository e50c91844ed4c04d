"""Run in simulator: a code lens on every program, and the server command it runs.

The lens runs ``mint.simulateFile`` on the server (VS Code's language client
turns server commands into editor commands; other clients send
``workspace/executeCommand``). The program and its paired configuration file
run in ``mint-run``'s simulator on a worker thread, bounded in simulated and
real time, so the server keeps answering meanwhile. The run shows as work done
progress the user can cancel (as can a ``$/cancelRequest`` of the command):
a program that loops forever stops at the next tick. What it printed goes to
an output document the editor is asked to show (``window/showDocument``); a
client that cannot show one gets the output's last lines in the message that
says how the run ended. The command answers with the JSON report of
``mint-run --report json``. The simulator is imported on the first run, not
when the server starts: most editing sessions never run one.
"""

from __future__ import annotations

import asyncio
import tempfile
import threading
import time
import uuid
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from lsprotocol import types
from pygls.uris import from_fs_path, to_fs_path

from mintlang.dialect import Dialect
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Settings, partner
from mintlang.semantic.units import Unit

if TYPE_CHECKING:
    from mintlang.runtime.run import RunResult

SIMULATE = "mint.simulateFile"
TITLE = "▶ Run in simulator"
UNTIL_MS, MAX_WALL_S = 600_000, 20.0  # ten simulated minutes, at most 20 s of the user's time
CANCELLED = "cancelled by the user"
REPORT_EVERY_S = 0.25  # progress reports while the run goes on
SHOWN_LINES = 20  # of the output, in the message of a client that cannot show a document
_RUNNABLE = frozenset({Dialect.V4, Dialect.MINTMT})


def lenses(server: MintServer, uri: str) -> list[types.CodeLens]:
    """One lens on the first line of a Mint v4 or MintMT program (configuration files run with their program;
    a v3 program runs on the v3 guide's controllers, which the editor's setting does not name); the code lens
    method is ``reference_lenses``', which shows this lens with the reference counts."""
    snapshot = server.snapshot(uri)
    if snapshot is None or snapshot.unit is Unit.CONFIGURATION or snapshot.skipped:
        return []
    if snapshot.settings.dialect not in _RUNNABLE:
        return []
    start = types.Position(line=0, character=0)
    command = types.Command(title=TITLE, command=SIMULATE, arguments=[uri])
    return [types.CodeLens(range=types.Range(start=start, end=start), command=command)]


def summary(result: RunResult) -> str:
    stop = result.stop
    where = f" at line {stop.line} ({stop.statement})" if stop.line is not None else ""
    why = f": {stop.message}" if stop.message else ""
    return f"Simulation {stop.reason.value} after {stop.time_ms} ms{where}{why}"


def output_text(name: str, result: RunResult) -> str:
    """The output document: how the run ended, then what the program printed."""
    dropped = result.terminal_dropped
    kept = f"(the first {dropped} characters printed are not kept)\n" if dropped else ""
    printed = result.terminal or "(the program printed nothing)\n"
    return f"{name}: {summary(result)}\n\n{kept}{printed}"


def _tail(text: str) -> str:
    lines = text.splitlines()
    shown = "\n".join(lines[-SHOWN_LINES:])
    return shown if len(lines) <= SHOWN_LINES else f"… ({len(lines) - SHOWN_LINES} lines before)\n{shown}"


class Watcher:
    """The run's observer on the worker thread: ends the run once cancelled, and reports progress."""

    def __init__(self, report: Callable[[int], None]) -> None:
        self.cancelled = threading.Event()
        self.report = report
        self.last = time.perf_counter()

    def on_tick(self, _: object, tick: int) -> None:
        if self.cancelled.is_set():
            from mintlang.runtime.simulation import Interrupt  # noqa: PLC0415 - see the module's docstring

            raise Interrupt(CANCELLED)
        now = time.perf_counter()
        if now - self.last >= REPORT_EVERY_S:
            self.last = now
            self.report(tick)


class Progress:
    """Work done progress shown by the client, cancellable; nothing where the client has none."""

    def __init__(self, server: MintServer, title: str) -> None:
        self.server = server
        self.title = title
        self.token = f"mint.simulate.{uuid.uuid4()}"
        self.started = time.perf_counter()
        self.shown = False

    async def begin(self, on_cancel: Callable[[], None]) -> None:
        window = self.server.client_capabilities.window
        if window is None or not window.work_done_progress:
            return
        try:
            await self.server.work_done_progress.create_async(self.token)
        except Exception:  # a client that refuses shows no progress; the run goes on
            return
        self.shown = True
        self.server.work_done_progress.tokens[self.token].add_done_callback(lambda _: on_cancel())
        begin = types.WorkDoneProgressBegin(title=self.title, cancellable=True, percentage=0)
        self.server.work_done_progress.begin(self.token, begin)

    def report(self, tick: int) -> None:
        """Called on the event loop: simulated time so far, and how much of the run's bounds it used."""
        if not self.shown:
            return
        wall = (time.perf_counter() - self.started) / MAX_WALL_S
        simulated = tick / UNTIL_MS
        message = f"{tick / 1000:.1f} s simulated"
        value = types.WorkDoneProgressReport(message=message, percentage=min(99, int(100 * max(wall, simulated))))
        self.server.work_done_progress.report(self.token, value)

    def end(self, message: str) -> None:
        if self.shown:
            self.server.work_done_progress.end(self.token, types.WorkDoneProgressEnd(message=message))
            self.server.work_done_progress.tokens.pop(self.token, None)  # pygls keeps every token otherwise


class Outputs:
    """Where output documents are written: a folder of this server's own, removed when it exits."""

    def __init__(self) -> None:
        self._folder: tempfile.TemporaryDirectory[str] | None = None

    def write(self, program_uri: str, text: str) -> str:
        """Write ``text`` as the output of the program and return the document's URI (one per program)."""
        if self._folder is None:
            self._folder = tempfile.TemporaryDirectory(prefix="mint-lsp-")
        name = Path(to_fs_path(program_uri) or "program").stem or "program"
        path = Path(self._folder.name) / f"{name} (simulator output).txt"
        path.write_text(text, encoding="utf-8")
        return from_fs_path(str(path)) or path.as_uri()


def _shows_documents(server: MintServer) -> bool:
    window = server.client_capabilities.window
    return bool(window and window.show_document and window.show_document.support)


def register(server: MintServer) -> None:
    outputs = Outputs()

    def error(message: str) -> None:
        server.window_show_message(types.ShowMessageParams(type=types.MessageType.Error, message=message))

    async def run(source: str, configuration: str | None, name: str, settings: Settings) -> RunResult:
        """The run on a worker thread, shown as progress; cancelled by the user or by ``$/cancelRequest``."""
        from mintlang.runtime.run import run_source  # noqa: PLC0415 - see the module's docstring
        from mintlang.runtime.simulation import Limits  # noqa: PLC0415

        loop = asyncio.get_running_loop()
        progress = Progress(server, f"Simulating {name}")
        watcher = Watcher(lambda tick: loop.call_soon_threadsafe(progress.report, tick))
        await progress.begin(watcher.cancelled.set)
        try:
            result = await asyncio.to_thread(
                run_source,
                source,
                config=configuration,
                controller=settings.controller,
                dialect=settings.dialect,
                limits=Limits(until_ms=UNTIL_MS, max_wall_s=MAX_WALL_S),
                on_tick=watcher.on_tick,
            )
        except asyncio.CancelledError:  # the request was cancelled: stop the worker too
            watcher.cancelled.set()
            progress.end(CANCELLED)
            raise
        except BaseException:
            progress.end("failed")
            raise
        progress.end(summary(result))
        return result

    @server.command(SIMULATE)
    async def simulate(ls: MintServer, uri: str) -> dict[str, Any] | None:
        from mintlang.runtime.report import as_json  # noqa: PLC0415 - see the module's docstring
        from mintlang.runtime.scenario import ScenarioFileError  # noqa: PLC0415

        settings = ls.analyses.settings_for(uri)
        unit, other = partner(uri, settings, ls.opened())
        # asked for a configuration file, run the program it configures
        program_uri, configuration_uri = (other, uri) if unit is Unit.CONFIGURATION and other else (uri, other)
        source = ls.read_text(program_uri)
        if source is None:
            error(f"Cannot read {program_uri} to simulate it")
            return None
        configuration = ls.read_text(configuration_uri) if configuration_uri is not None else None
        name = Path(to_fs_path(program_uri) or program_uri).name
        try:
            result = await run(source, configuration, name, settings.for_text(source))
        except ScenarioFileError as problem:
            error(str(problem))
            return None
        text = output_text(name, result)
        document = outputs.write(program_uri, text)
        shown = False
        if _shows_documents(ls):
            answer = await ls.window_show_document_async(types.ShowDocumentParams(uri=document, take_focus=False))
            shown = bool(answer and answer.success)
        message = summary(result) if shown else f"{summary(result)}\n{_tail(result.terminal)}".rstrip()
        ls.window_show_message(types.ShowMessageParams(type=_severity(result), message=message))
        return as_json(result)


def _severity(result: RunResult) -> types.MessageType:
    from mintlang.runtime.interpreter.vm import StopReason  # noqa: PLC0415 - imported by the run before

    reason = result.stop.reason
    if reason in (StopReason.END, StopReason.UNTIL):
        return types.MessageType.Info
    return types.MessageType.Warning if reason is StopReason.INTERRUPTED else types.MessageType.Error
