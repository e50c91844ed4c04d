"""The DAP session: requests in, responses and events out, over one pair of byte streams.

Requests are served one at a time on the reading thread; the program runs on
the execution's thread and reports through ``stopped``, ``output`` and
``finished``. Anything a request gets wrong is an error response with a
message the editor shows, never a traceback.
"""

from __future__ import annotations

import contextlib
import re
import sys
import threading
from collections.abc import Callable
from pathlib import Path
from typing import Any, BinaryIO

from mintlang.cli.report import shortened
from mintlang.runtime.controller import Controller
from mintlang.runtime.debugger import stepping
from mintlang.runtime.debugger.breakpoints import Breakpoints
from mintlang.runtime.debugger.evaluation import EvaluationError, Evaluator, shown
from mintlang.runtime.debugger.execution import ERRORS, UNHANDLED, Execution
from mintlang.runtime.debugger.framing import FramingError, read_message, write_message
from mintlang.runtime.debugger.launch import Application, LaunchError, Layout, layout, prepare
from mintlang.runtime.debugger.variables import NotSettable, References, scopes
from mintlang.runtime.interpreter.vm import Frame, Site, StopReason
from mintlang.runtime.run import RunResult
from mintlang.syntax.lexer import lex
from mintlang.syntax.nodes import identity
from mintlang.syntax.tokens import TokenKind

THREAD_ID = 1  # the program is one thread of control; event handlers run on it
_NAMES = frozenset({TokenKind.NAME, TokenKind.LABEL})  # the tokens that write a user's name
_QUOTED = re.compile(r'"([^"]*)"')  # keys typed in the debug console

CAPABILITIES: dict[str, Any] = {
    "supportsConfigurationDoneRequest": True,
    "supportsConditionalBreakpoints": True,
    "supportsHitConditionalBreakpoints": True,
    "supportsFunctionBreakpoints": True,
    "supportsLogPoints": True,
    "supportsEvaluateForHovers": True,
    "supportsSetVariable": True,
    "supportsStepBack": True,
    "supportsTerminateRequest": True,
    "supportsRestartRequest": False,
    "exceptionBreakpointFilters": [
        {
            "filter": UNHANDLED,
            "label": "Errors that end the run",
            "description": "Stop where an error no #ONERROR handles, or a wait nothing can end, ends the run",
            "default": True,
        },
        {
            "filter": ERRORS,
            "label": "Every run-time error",
            "description": "Stop at each run-time error as it is raised, before #ONERROR runs",
            "default": False,
        },
    ],
}


NOT_DEBUGGING = "the program runs without debugging (noDebug): it stops at no breakpoint"


class RequestError(Exception):
    """A request that cannot be served; its message becomes the error response's."""


class Session:
    def __init__(self, reader: BinaryIO, writer: BinaryIO) -> None:
        self.reader = reader
        self.writer = writer
        self._sequence = 0
        self._writing = threading.Lock()
        self.application: Application | None = None
        self.breakpoints: Breakpoints | None = None
        self.execution: Execution | None = None
        self.exception_filters = frozenset({UNHANDLED})
        self.references = References()
        self.spellings: dict[str, str] = {}
        self.layout = Layout()
        self.first_column = 1  # the client's number for a line's first column
        self.initialized = False  # an initialize answered: a client whose initialize failed would count lines wrongly
        self._handlers: dict[str, Callable[[dict[str, Any]], dict[str, Any] | None]] = {
            "initialize": self.initialize,
            "launch": self.launch,
            "setBreakpoints": self.set_breakpoints,
            "setFunctionBreakpoints": self.set_function_breakpoints,
            "setExceptionBreakpoints": self.set_exception_breakpoints,
            "configurationDone": self.configuration_done,
            "threads": self.threads,
            "stackTrace": self.stack_trace,
            "scopes": self.scopes,
            "variables": self.variables,
            "setVariable": self.set_variable,
            "evaluate": self.evaluate,
            "continue": self.cont,
            "next": self.step(stepping.step_over),
            "stepIn": self.step(stepping.step_in),
            "stepOut": self.step(stepping.step_out),
            "stepBack": self.step_back,
            "runFor": self.run_for,
            "reverseContinue": self.reverse_continue,
            "pause": self.pause,
            "terminate": self.terminate,
            "disconnect": self.disconnect,
        }

    # ------------------------------------------------------------------ the loop

    def serve(self) -> None:
        """Serve requests until ``disconnect`` or the end of the input."""
        while True:
            try:
                message = read_message(self.reader)
            except FramingError as error:
                self.send_event("output", {"category": "important", "output": f"mint-dap: {error}\n"})
                continue
            if message is None:
                break
            if message.get("type") == "request":
                self.handle(message)
                if message.get("command") == "disconnect":
                    break
        if self.execution is not None:
            self.execution.terminate()

    def handle(self, request: dict[str, Any]) -> None:
        command = str(request.get("command", ""))
        handler = self._handlers.get(command)
        arguments = request.get("arguments") or {}
        try:
            if handler is None:
                raise RequestError(f"{command!r} is not supported by mint-dap")
            if not isinstance(arguments, dict):
                raise RequestError("the request's arguments are not an object")
            thread = arguments.get("threadId", THREAD_ID)
            if type(thread) is not int or thread != THREAD_ID:  # DAP: a request for an unknown thread fails
                raise RequestError(f"there is no thread {thread!r}: the program is thread {THREAD_ID}")
            body = handler(arguments)
        except (RequestError, LaunchError, EvaluationError, NotSettable) as error:
            self.respond(request, None, str(error))
            return
        except Exception as error:  # a bug of ours: the editor gets a message, the session goes on
            print(f"mint-dap: internal error in {command}: {error!r}", file=sys.stderr)
            self.respond(request, None, f"internal error in mint-dap: {error}")
            return
        self.respond(request, body)
        if command == "launch":  # ready for the configuration requests: breakpoints bind to its statements
            self.send_event("initialized")

    def respond(self, request: dict[str, Any], body: dict[str, Any] | None, error: str | None = None) -> None:
        message: dict[str, Any] = {
            "type": "response",
            "request_seq": request.get("seq", 0),
            "command": request.get("command", ""),
            "success": error is None,
        }
        if error is not None:
            message["message"] = error
            message["body"] = {"error": {"id": 1, "format": error.replace("{", "{{").replace("}", "}}")}}
        elif body is not None:
            message["body"] = body
        self.send(message)

    def send_event(self, event: str, body: dict[str, Any] | None = None) -> None:
        message: dict[str, Any] = {"type": "event", "event": event}
        if body is not None:
            message["body"] = body
        self.send(message)

    def send(self, message: dict[str, Any]) -> None:
        with self._writing:
            self._sequence += 1
            message["seq"] = self._sequence
            with contextlib.suppress(BrokenPipeError, ValueError):  # the editor went away: nothing left to tell it
                write_message(self.writer, message)

    # --------------------------------------------------- the execution's reports

    def stopped(self, reason: str, description: str | None) -> None:
        self.references.clear()
        body: dict[str, Any] = {"reason": reason, "threadId": THREAD_ID, "allThreadsStopped": True}
        if description is not None:
            body["description"] = description
            body["text"] = description
        self.send_event("stopped", body)

    def output(self, text: str, category: str) -> None:
        self.send_event("output", {"category": category, "output": text})

    def finished(self, result: RunResult | None, problem: str | None) -> None:
        if problem is not None:
            self.output(f"mint-dap: {problem}\n", "stderr")
        if result is not None:
            self.output(_ending(result), "console")
            normal = result.stop.reason in (StopReason.END, StopReason.UNTIL)
            self.send_event("exited", {"exitCode": 0 if normal else 1})
        self.send_event("terminated")

    # -------------------------------------------------------------- the requests

    def initialize(self, arguments: dict[str, Any]) -> dict[str, Any]:
        if not arguments.get("linesStartAt1", True):
            raise RequestError("mint-dap counts lines from 1, as Mint does: the client must too")
        self.first_column = 1 if arguments.get("columnsStartAt1", True) else 0
        self.initialized = True
        return CAPABILITIES

    def launch(self, arguments: dict[str, Any]) -> None:
        if not self.initialized:  # DAP: initialize comes first; a refused one (lines from 0) is not an answer
            raise RequestError("no initialize has succeeded: send initialize, counting lines from 1, first")
        if self.application is not None:
            raise RequestError("this session has already launched a program")
        application = prepare(arguments)
        self.layout = layout(application)
        self.breakpoints = Breakpoints(self.layout)
        self.spellings = _spellings(application)
        self.application = application

    def set_breakpoints(self, arguments: dict[str, Any]) -> dict[str, Any]:
        application, breakpoints = self._launched()
        source = arguments.get("source") or {}
        if not isinstance(source, dict):
            raise RequestError('\'source\' is an object, such as {"path": "cell.mnt"}')
        unit = _unit_of(application, source.get("path"))
        requested = arguments.get("breakpoints")
        if requested is None:
            requested = [{"line": line} for line in _listed(arguments.get("lines", []), "lines")]
        requested = _objects(requested, "breakpoints")
        if unit is None or not application.debugging:
            problem = "not part of the program being debugged" if application.debugging else NOT_DEBUGGING
            return {"breakpoints": [{"verified": False, "message": problem} for _ in requested]}
        placed = breakpoints.replace(unit, requested)
        return {"breakpoints": [breakpoint_.as_dap(source) for breakpoint_ in placed]}

    def set_function_breakpoints(self, arguments: dict[str, Any]) -> dict[str, Any]:
        application, breakpoints = self._launched()
        requested = _objects(arguments.get("breakpoints", []), "breakpoints")
        if not application.debugging:
            return {"breakpoints": [{"verified": False, "message": NOT_DEBUGGING} for _ in requested]}
        placed = breakpoints.replace_functions(requested)
        return {
            "breakpoints": [
                item.as_dap(_source(application, item.unit) if item.pc is not None else None) for item in placed
            ]
        }

    def set_exception_breakpoints(self, arguments: dict[str, Any]) -> dict[str, Any]:
        names = _listed(arguments.get("filters", []), "filters")
        if not all(isinstance(name, str) for name in names):
            raise RequestError(f"'filters' is a list of names: {ERRORS}, {UNHANDLED}")
        filters = frozenset(names)
        unknown = filters - {ERRORS, UNHANDLED}
        if unknown:
            raise RequestError(f"no exception filter {', '.join(sorted(unknown))}: use {ERRORS} or {UNHANDLED}")
        self.exception_filters = filters
        if self.execution is not None:
            self.execution.exception_filters = self._stopping_at(filters)
        return {"breakpoints": [{"verified": True} for _ in filters]}

    def configuration_done(self, arguments: dict[str, Any]) -> None:
        application, breakpoints = self._launched()
        if self.execution is not None:
            raise RequestError("the program is already running")
        self.execution = Execution(application, breakpoints, self)
        self.execution.exception_filters = self._stopping_at(self.exception_filters)
        self.execution.start(stepping.entry() if application.stop_on_entry else stepping.cont(-1))

    def threads(self, arguments: dict[str, Any]) -> dict[str, Any]:
        name = self.application.program.name if self.application is not None else "program"
        return {"threads": [{"id": THREAD_ID, "name": name}]}

    def stack_trace(self, arguments: dict[str, Any]) -> dict[str, Any]:
        execution, controller = self._paused()
        assert execution.point is not None
        vm = controller.vm
        frames = []
        pc = execution.point.pc
        for depth, frame in enumerate([*reversed(vm.frames), None]):
            pc = self.layout.shown(pc)
            frames.append(self._frame(depth, self._site(pc, execution), pc, frame, controller))
            if frame is None:
                break
            pc = frame.entered_at  # the GOSUB, the statement #ONERROR's error came from, where an event broke in
        start = _whole(arguments.get("startFrame", 0), "'startFrame'")
        levels = _whole(arguments.get("levels", 0), "'levels'")
        shown_frames = frames[start : start + levels] if levels > 0 else frames[start:]
        return {"stackFrames": shown_frames, "totalFrames": len(frames)}

    @staticmethod
    def _site(pc: int, execution: Execution) -> Site | None:
        """The statement at ``pc``; past the last one, where the run ended (a file the compiler refused)."""
        sites = execution.controller.vm.sites if execution.controller is not None else []
        if pc < len(sites):
            return sites[pc]
        ending = execution.ending
        if ending is not None and ending.unit is not None and ending.line is not None:
            return Site(ending.unit, ending.line, ending.statement or "")
        return sites[-1] if sites else None

    def _frame(
        self, depth: int, site: Site | None, pc: int, opened: Frame | None, controller: Controller
    ) -> dict[str, Any]:
        assert self.application is not None
        name = self._routine(site, opened, controller)
        column = self.layout.column(pc) if site is not None and pc < len(self.layout.sites) else 1
        column += self.first_column - 1
        frame: dict[str, Any] = {"id": depth + 1, "name": name, "line": site.line if site else 0, "column": column}
        source = _source(self.application, site.unit) if site is not None else None
        if source is not None:
            frame["source"] = source
        return frame

    def _routine(self, site: Site | None, opened: Frame | None, controller: Controller) -> str:
        """The name of a frame: the subroutine or handler its call ``opened``, by the label its code starts at (a
        label a GOTO jumps to opens none); the outermost frame is its file's."""
        if site is None:
            return "program"
        if opened is None:
            return site.unit
        linked = controller.linked
        unit = controller.vm.sites[opened.target].unit if opened.target < len(controller.vm.sites) else site.unit
        labels = linked.handlers if unit == "program" else linked.configuration_handlers
        called = [label for label, start in labels.items() if start == opened.target]
        if not called:
            return site.unit
        label = called[-1]  # of labels on lines in a row, the one nearest the code
        return "#" + self.spellings.get(label, label)

    def scopes(self, arguments: dict[str, Any]) -> dict[str, Any]:
        execution, controller = self._paused()
        assert execution.evaluator is not None
        frame = _whole(arguments.get("frameId"), "'frameId'")
        if not 1 <= frame <= len(controller.vm.frames) + 1:  # stackTrace's ids: 1, the top, to the program's
            raise RequestError(f"no frame {frame} at this stop")  # Mint's variables are global: one set for all
        found = []
        for name, node, count in scopes(controller, execution.evaluator, self.spellings):
            reference = self.references.add(node, count > 0)
            scope: dict[str, Any] = {"name": name, "variablesReference": reference, "expensive": False}
            if count:
                scope["indexedVariables"] = count
            found.append(scope)
        return {"scopes": found}

    def variables(self, arguments: dict[str, Any]) -> dict[str, Any]:
        self._paused()
        reference = _whole(arguments.get("variablesReference"), "'variablesReference'")
        count = arguments.get("count")
        count = None if count is None else _whole(count, "'count'")
        kind = arguments.get("filter")
        if kind not in (None, "named", "indexed"):
            raise RequestError(f"'filter' is named or indexed, not {kind!r}")
        try:
            listed = self.references.listed(reference, _whole(arguments.get("start"), "'start'"), count, kind)
        except KeyError:
            raise RequestError(f"no variables under reference {reference} at this stop") from None
        return {"variables": listed}

    def set_variable(self, arguments: dict[str, Any]) -> dict[str, Any]:
        execution, _ = self._paused()
        assert execution.evaluator is not None
        reference = _whole(arguments.get("variablesReference"), "'variablesReference'")
        node = self.references.nodes.get(reference)
        if node is None:
            raise RequestError(f"no variables under reference {reference} at this stop")
        value = self._value(execution.evaluator, str(arguments.get("value", "")))
        description, apply = node.assignment(str(arguments.get("name", "")), value)
        execution.intervene(description, apply)
        return {"value": shown(value)}

    def evaluate(self, arguments: dict[str, Any]) -> dict[str, Any]:
        """A Mint expression's value; in the debug console, a quoted string is typed at the controller's
        keyboard instead (``"Y"``, ``"12\\r"``), for ``INKEY`` and ``INPUT`` to read as the program goes on."""
        execution, _ = self._paused()
        assert execution.evaluator is not None
        text = str(arguments.get("expression", ""))
        typed = _QUOTED.fullmatch(text.strip())
        if arguments.get("context") == "repl" and typed is not None:
            keys = typed.group(1).replace("\\r", "\r").replace("\\n", "\n")
            execution.intervene(f"typed {text.strip()}", lambda controller: controller.terminal.type_keys(keys))
            return {"result": f"typed {len(keys)} key{'' if len(keys) == 1 else 's'}", "variablesReference": 0}
        if arguments.get("context") == "repl" and execution.evaluator.reader.assigns(text):
            raise EvaluationError(
                f"{text.strip()} is an assignment, which the debug console does not run: it evaluates expressions; "
                "set a variable in the Variables view (setVariable)"
            )
        return {"result": shown(self._value(execution.evaluator, text)), "variablesReference": 0}

    def _value(self, evaluator: Evaluator, text: str) -> float:
        """``text``'s value; where the compiler refused the program, a failure says so: none of its names exist."""
        try:
            return evaluator.evaluate(text)
        except EvaluationError as error:
            if self.layout.refused is None:
                raise
            raise EvaluationError(
                f"{error}: the program does not compile, so none of its variables exist: {self.layout.refused}"
            ) from None

    def cont(self, arguments: dict[str, Any]) -> dict[str, Any]:
        execution, _ = self._paused()
        assert execution.point is not None
        execution.resume(stepping.cont(execution.point.count))
        return {"allThreadsContinued": True}

    def step(self, plan: Callable[[stepping.Point], stepping.Forward]) -> Callable[[dict[str, Any]], None]:
        def request(arguments: dict[str, Any]) -> None:
            execution, _ = self._paused()
            assert execution.point is not None
            execution.resume(plan(execution.point))

        return request

    def run_for(self, arguments: dict[str, Any]) -> None:
        """``runFor {"ms": 100}``, mint-dap's own request: run on for that much simulated time."""
        execution, _ = self._paused()
        assert execution.point is not None
        ms = arguments.get("ms")
        if not isinstance(ms, int) or isinstance(ms, bool) or ms < 1:
            raise RequestError("runFor takes 'ms', a whole number of simulated milliseconds, 1 or more")
        execution.resume(stepping.run_for(execution.point, ms))

    def step_back(self, arguments: dict[str, Any]) -> None:
        execution, _ = self._paused()
        assert execution.point is not None
        execution.step_back(execution.point)

    def reverse_continue(self, arguments: dict[str, Any]) -> None:
        execution, _ = self._paused()
        assert execution.point is not None and self.breakpoints is not None
        execution.reverse_continue(execution.point)

    def pause(self, arguments: dict[str, Any]) -> None:
        if self.execution is None:
            raise RequestError("the program has not started: send configurationDone first")
        if self.execution.point is None:
            self.execution.pause()

    def terminate(self, arguments: dict[str, Any]) -> None:
        if self.execution is None:
            self.send_event("terminated")
            return
        self.execution.terminate()

    def disconnect(self, arguments: dict[str, Any]) -> None:
        if self.execution is not None:
            self.execution.terminate()

    # ------------------------------------------------------------------- helpers

    def _stopping_at(self, filters: frozenset[str]) -> frozenset[str]:
        """The errors the run stops at: those the editor chose, none in a run without debugging."""
        return filters if self.application is None or self.application.debugging else frozenset()

    def _launched(self) -> tuple[Application, Breakpoints]:
        if self.application is None or self.breakpoints is None:
            raise RequestError("launch a program first")
        return self.application, self.breakpoints

    def _paused(self) -> tuple[Execution, Controller]:
        execution = self.execution
        if execution is None or execution.point is None or execution.controller is None:
            raise RequestError("the program is not paused")
        return execution, execution.controller


def _listed(value: object, name: str) -> list[Any]:
    if not isinstance(value, list):
        raise RequestError(f"'{name}' is a list")
    return value


def _objects(value: object, name: str) -> list[dict[str, Any]]:
    """A request's list of objects (breakpoints); a malformed one is refused, not half read."""
    if not all(isinstance(item, dict) for item in _listed(value, name)):
        raise RequestError(f"'{name}' is a list of objects")
    return value  # type: ignore[return-value]


def _whole(value: object, name: str) -> int:
    """A whole number 0 or more that a request gives (a line, a frame's index); 0 when absent."""
    if value is None:
        return 0
    if not isinstance(value, int) or isinstance(value, bool) or value < 0:
        raise RequestError(f"{name} is a whole number, 0 or more, not {value!r}")
    return value


def _spellings(application: Application) -> dict[str, str]:
    """Each name's spelling as the code first writes it, by the identity the interpreter files it under: a
    comment's or a string's words are not names (``' the timer`` above ``Event TIMER`` is not its spelling)."""
    spellings: dict[str, str] = {}
    for text in (application.configuration_source or "", application.source):
        for _, line in lex(text, application.dialect).lines:
            for kind, word in zip(line.kinds, line.texts, strict=True):
                if kind in _NAMES:
                    name = word.lstrip("#")
                    spellings.setdefault(identity(name), name)
    return spellings


def _source(application: Application, unit: str) -> dict[str, Any] | None:
    path = application.path_of(unit)
    return {"name": path.name, "path": str(path.resolve())} if path is not None else None


def _unit_of(application: Application, path: object) -> str | None:
    if not isinstance(path, str) or "\0" in path:  # a NUL character: no file's path, and os.stat would raise
        return None
    for unit in ("program", "configuration"):
        known = application.path_of(unit)
        if known is not None and Path(path).resolve() == known.resolve():
            return unit
    return None


def _ending(result: RunResult) -> str:
    stop = result.stop
    line = f"{stop.reason.value} after {stop.time_ms} ms"
    if stop.line is not None:
        line += f" at {stop.unit} line {stop.line}: {shortened(stop.statement or '')}"
    if stop.message:
        line += f" — {stop.message}"
    return line + "\n"
