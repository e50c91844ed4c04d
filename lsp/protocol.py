"""The JSON-RPC layer: every request is answered, and nothing of a finished message is kept.

pygls 2.1 leaves a client waiting, or the server growing, in four places:

- a request whose params do not fit the method (none, an array, a negative
  position) fails while it is decoded, before pygls knows it is a request:
  pygls logs it and shows an error, but never answers, so the client waits
  forever. The LSP wants ``InvalidParams``;
- a request before ``initialize`` reaches a handler that needs the workspace
  and fails with an internal error and a traceback; the LSP wants
  ``ServerNotInitialized``, and notifications dropped (``exit`` excepted);
- a request after ``shutdown`` is dropped silently; the LSP wants ``InvalidRequest``;
- every notification, and every handler a built-in one hands on to, is filed
  under a fresh id in the table of requests in flight and never taken out:
  a ``Future``, a task and its context per keystroke, 3 KB an edit;
- a ``$/cancelRequest`` of a request a built-in handler hands on (a command of
  ``workspace/executeCommand``) answers it as cancelled but leaves the
  command running: a simulation went on for its full 20 s;
- a body that is not JSON (or nested too deeply for ``json``), or JSON that is
  no message (``[]``, ``5``), is logged with a traceback and shown to the user
  as a server error, but never answered; JSON-RPC wants ``ParseError`` or
  ``InvalidRequest`` with a null id;
- a notification whose params do not fit the method is logged with a
  traceback and shown to the user as a server error: the client's mistake,
  which no answer can tell it, is dropped with one line in the log.
"""

from __future__ import annotations

import json
import logging
import weakref
from collections.abc import Callable, Generator
from concurrent.futures import Future
from functools import partial
from typing import Any

import cattrs
from lsprotocol import types
from pygls.exceptions import (
    JsonRpcException,
    JsonRpcInternalError,
    JsonRpcInvalidParams,
    JsonRpcInvalidRequest,
    JsonRpcParseError,
    JsonRpcServerNotInitialized,
)
from pygls.protocol import lsp_method

from mintlang.lsp.documents import LspProtocol

log = logging.getLogger(__name__)

_ANSWERED = object()  # a request refused while it was decoded: its error response has gone out
# what json.loads raises for a body that is not JSON, or one nested thousands deep (it recurses once a level)
UNREADABLE = (json.JSONDecodeError, UnicodeDecodeError, RecursionError)


def _why(error: JsonRpcException) -> str:
    """What was wrong with the params, as paths into them (``required field missing @ $.params.position``)."""
    cause = error.__cause__
    if isinstance(cause, cattrs.ClassValidationError | cattrs.IterableValidationError):
        return "; ".join(cattrs.transform_error(cause))
    return str(cause or error)


def _cancel_with(handed: weakref.ref[Any], request: Future[Any]) -> None:
    """``request`` is done: if it was cancelled, so is the handler it was handed on to, if that still runs."""
    inner = handed()
    if request.cancelled() and inner is not None:
        inner.cancel()


class MintProtocol(LspProtocol):
    """pygls' protocol, answering every request it cannot run and forgetting finished handlers."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self._initialize_received = False
        self._handing_on: Future[Any] | None = None  # the request whose built-in handler is handing on

    def structure_message(self, data: dict[str, Any]) -> Any:
        """A request whose params cannot be read is answered with ``InvalidParams`` here, as it is decoded."""
        try:
            return super().structure_message(data)
        except JsonRpcException as error:
            if "method" not in data:
                raise  # a response: pygls logs and shows it
            if "id" not in data:  # a notification has nobody to answer
                log.warning("dropped %s: %s", data["method"], _why(error))
                return _ANSWERED
            message = f"{JsonRpcInvalidParams.MESSAGE} for {data['method']}: {_why(error)}"
            self._send_response(data["id"], error=JsonRpcInvalidParams(message).to_response_error())
            return _ANSWERED

    def handle_message(self, message: Any) -> None:
        if message is _ANSWERED:
            return
        if not hasattr(message, "jsonrpc"):  # valid JSON, but a list, a number, a string: no message
            self._refuse(None, JsonRpcInvalidRequest(f"not a JSON-RPC message: {str(message)[:80]}"))
            return
        method = getattr(message, "method", None)
        request = method is not None and getattr(message, "id", None) is not None
        if method == types.INITIALIZE:
            self._initialize_received = True
        elif not self._initialize_received and method != types.EXIT:
            if request:
                self._refuse(message.id, JsonRpcServerNotInitialized(f"{method} before initialize"))
            return  # a notification before initialize is dropped
        elif self._shutdown and request:
            self._refuse(message.id, JsonRpcInvalidRequest(f"{method} after shutdown"))
            return
        super().handle_message(message)

    def _refuse(self, msg_id: Any, error: JsonRpcException) -> None:
        log.warning("refused: %s", error.message)
        if msg_id is None:  # pygls leaves a null id out, and JSON-RPC wants it there
            response_error = {"code": error.code, "message": error.message}
            self._send_data({"jsonrpc": self.VERSION, "id": None, "error": response_error})
            return
        self._send_response(msg_id, error=error.to_response_error())

    def refuse_unreadable(self, error: Exception) -> None:
        """A body that is not JSON: ``ParseError``, with a null id as nothing of it can be read."""
        self._refuse(None, JsonRpcParseError(f"{JsonRpcParseError.MESSAGE}: {error}"))

    def _execute_handler(
        self,
        msg_id: Any,
        handler: Callable[..., Any],
        callback: Callable[[Future[Any]], None],
        args: tuple[Any, ...] | None = None,
        kwargs: dict[str, Any] | None = None,
    ) -> None:
        """pygls' dispatch, then the handler's entry in the requests in flight dropped once it is done
        (pygls drops it only for the requests it answers), and a handler a built-in one handed a request
        to cancelled with that request."""
        request = self._handing_on
        super()._execute_handler(msg_id, handler, callback, args, kwargs)
        future = self._request_futures.get(msg_id)
        if future is None:
            return
        future.add_done_callback(lambda done: self._forget(msg_id, done))
        if request is not None:  # weakly: a cycle of futures outlives the frozen collector (``Collector``)
            request.add_done_callback(partial(_cancel_with, weakref.ref(future)))

    def _run_generator(
        self, future: Future[Any] | None, *, gen: Generator[Any, Any, Any], result_future: Future[Any]
    ) -> None:
        """pygls runs a built-in handler's next step; the handler it hands on to is linked to ``result_future``."""
        outer, self._handing_on = self._handing_on, result_future
        try:
            super()._run_generator(future, gen=gen, result_future=result_future)
        finally:
            self._handing_on = outer

    def _forget(self, msg_id: Any, done: Future[Any]) -> None:
        if self._request_futures.get(msg_id) is done:
            del self._request_futures[msg_id]

    @lsp_method(types.SHUTDOWN)
    def lsp_shutdown(self, *args: Any) -> Generator[Any, Any, None]:
        """pygls' shutdown cancels what is in flight while it walks the table, and a cancelled future now
        leaves the table at once: the ones that would, cancelled first over a copy."""
        current = self.msg_id
        for msg_id, future in list(self._request_futures.items()):
            if msg_id != current and isinstance(future, Future):
                future.cancel()
        return (yield from super().lsp_shutdown(*args))


class ParseErrorsInOneLine(logging.Filter):
    """pygls logs a body that is not JSON with its traceback; the error is the client's, one line says it."""

    def filter(self, record: logging.LogRecord) -> bool:
        if record.exc_info is not None and isinstance(record.exc_info[1], UNREADABLE):
            record.msg, record.args = "unreadable message: %s", (record.exc_info[1],)
            record.exc_info, record.exc_text = None, None
        return True


class RefusalsInOneLine(logging.Filter):
    """pygls logs a request its handler refused on purpose (``JsonRpcException``: a command no server has, a
    name no rename takes) with a traceback, though it answers it with the error; the client's mistake is one
    line. An internal error keeps its traceback: that one is ours."""

    def filter(self, record: logging.LogRecord) -> bool:
        refused = record.exc_info[1] if record.exc_info is not None else None
        if isinstance(refused, JsonRpcException) and not isinstance(refused, JsonRpcInternalError):
            said = record.args if isinstance(record.args, tuple) else ()  # the message id
            record.msg, record.args = "refused request %s: %s", (*said[:1], refused.message)
            record.exc_info, record.exc_text = None, None
        return True


class DecodeErrorsInOneLine(logging.Filter):
    """pygls logs params it cannot decode with its converter's traceback before the request is answered
    with ``InvalidParams``; the error is the client's, and the exception's own line says what was wrong."""

    def filter(self, record: logging.LogRecord) -> bool:
        if record.msg == "Unable to deserialize message\n%s" and record.args:
            lines = [line.strip(" |") for line in str(record.args[0]).splitlines()]
            said = [line for line in lines if ": " in line and line.split(":")[0].endswith(("Error", "Exception"))]
            record.msg, record.args = "undecodable message: %s", (said[-1] if said else lines[-1],)
        return True
