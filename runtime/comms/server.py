"""The host port: host packets over TCP on 127.0.0.1, applied by the simulation thread at tick boundaries.

A daemon thread only moves bytes (accepts, receives into per-connection inboxes, sends queued
replies). Decoding and every effect on the comms array happen in ``service``, which the simulation
calls once per servo tick, so a run's behaviour depends only on which tick the bytes arrived in,
and replies leave at the next tick (CM-6 RC).
"""

from __future__ import annotations

import contextlib
import os
import selectors
import socket
import threading
import time
from dataclasses import dataclass, field
from types import TracebackType
from typing import Self

from mintlang.runtime.comms import PortUnavailable
from mintlang.runtime.comms.packets import HostEndpoint, PacketDecoder

_RECEIVE_SIZE = 4096
_FLUSH_SECONDS = 1.0
_INBOX_LIMIT = 1 << 16
"""Bytes held per connection before reading pauses: a flooding client is slowed by TCP, not by memory."""
_OUTBOX_LIMIT = 1 << 16
"""Unsent reply bytes per connection before reading pauses: a client that never reads its replies is
slowed by TCP as it would be by a serial line's flow control, and the queue of replies stays bounded. Each
socket's send buffer gets the same size: left to grow, the kernel's share alone reaches megabytes."""


@dataclass(slots=True, eq=False)
class _Connection:
    """One client; ``decoder`` belongs to the simulation thread, the rest is shared under the server's lock.

    ``ended``: the client has finished sending (a half close), but may still be reading its replies.
    ``answered``: every byte of an ended client has been serviced, so it is closed once its replies are sent.
    """

    sock: socket.socket
    decoder: PacketDecoder = field(default_factory=PacketDecoder)
    inbox: bytearray = field(default_factory=bytearray)
    outbox: bytearray = field(default_factory=bytearray)
    watched: int = 0
    open: bool = True
    ended: bool = False
    answered: bool = False


class HostPortServer:
    """A TCP host port; each connection is its own byte stream with its own packet decoder.

    Threading contract: create, ``service`` and ``close`` from the simulation thread; ``port`` from
    anywhere. Client misbehaviour (garbage, half packets, resets) never raises here: a closed
    connection's received bytes are still serviced once, and its replies are dropped. A client that
    only ends its sending side still gets the replies to what it sent, then the connection closes.
    """

    def __init__(self, port: int = 0) -> None:
        try:
            self._listener = socket.create_server(("127.0.0.1", port))
        except OSError as problem:  # in use, or a privileged port
            reason = os.strerror(problem.errno) if problem.errno else str(problem)  # not create_server's long wording
            raise PortUnavailable(f"cannot listen on 127.0.0.1:{port}: {reason}") from None
        self._listener.setblocking(False)
        self._wake_reader, self._wake_writer = socket.socketpair()
        self._wake_reader.setblocking(False)
        self._wake_writer.setblocking(False)
        self._selector = selectors.DefaultSelector()
        self._selector.register(self._listener, selectors.EVENT_READ)
        self._selector.register(self._wake_reader, selectors.EVENT_READ)
        self._lock = threading.Lock()
        self._connections: list[_Connection] = []
        self._closing = threading.Event()
        self._thread = threading.Thread(target=self._run, name="mint-host-port", daemon=True)
        self._thread.start()

    @property
    def port(self) -> int:
        """The bound port, useful when the server was asked for port 0."""
        return self._listener.getsockname()[1]

    def service(self, endpoint: HostEndpoint) -> None:
        """Decode the bytes received since the last call, apply them through ``endpoint`` and queue the replies."""
        with self._lock:
            batch = [
                (connection, bytes(connection.inbox), connection.ended)
                for connection in self._connections
                if connection.inbox or (connection.ended and not connection.answered)
            ]
            for connection, _, _ in batch:
                connection.inbox.clear()
            self._connections = [connection for connection in self._connections if connection.open]
        if not batch:
            return
        replies = [
            (connection, b"".join(endpoint.answer(request) for request in connection.decoder.feed(data)), ended)
            for connection, data, ended in batch
        ]
        with self._lock:
            for connection, reply, ended in replies:
                if connection.open:
                    connection.outbox += reply
                connection.answered = ended
        self._wake()

    def close(self) -> None:
        """Send the replies still queued (for up to a second), then stop the I/O thread and close every socket.

        A run often ends on the tick that applied a host's last write; its ACK must still reach the host.
        Calling ``close`` again does nothing.
        """
        if self._closing.is_set():
            return
        deadline = time.monotonic() + _FLUSH_SECONDS
        while time.monotonic() < deadline and self._replies_pending():
            time.sleep(0.001)
        self._closing.set()
        self._wake()
        self._thread.join()
        with self._lock:
            connections, self._connections = self._connections, []
        for connection in connections:
            connection.open = False
            connection.sock.close()
        self._selector.close()
        for sock in (self._listener, self._wake_reader, self._wake_writer):
            sock.close()

    def _replies_pending(self) -> bool:
        with self._lock:
            return any(connection.open and connection.outbox for connection in self._connections)

    def __enter__(self) -> Self:
        return self

    def __exit__(
        self, kind: type[BaseException] | None, error: BaseException | None, traceback: TracebackType | None
    ) -> None:
        self.close()

    def _wake(self) -> None:
        """Interrupt the I/O thread's ``select``; a full wake-up socket already means a wake-up is pending."""
        with contextlib.suppress(OSError):
            self._wake_writer.send(b"\0")

    def _run(self) -> None:
        while not self._closing.is_set():
            self._update_watches()
            for key, events in self._selector.select():
                if key.fileobj is self._listener:
                    self._accept()
                elif key.fileobj is self._wake_reader:
                    with contextlib.suppress(OSError):
                        self._wake_reader.recv(_RECEIVE_SIZE)
                else:
                    connection: _Connection = key.data
                    if events & selectors.EVENT_READ:
                        self._receive(connection)
                    if events & selectors.EVENT_WRITE and connection.open:
                        self._send(connection)

    def _update_watches(self) -> None:
        """Read while the client sends and both the inbox and the unsent replies have room, write while replies
        wait; a connection wanting neither is unregistered, and closed once an ended client has had all its replies."""
        with self._lock:
            wanted = [
                (
                    connection,
                    (selectors.EVENT_READ if not connection.ended and self._has_room(connection) else 0)
                    | (selectors.EVENT_WRITE if connection.outbox else 0),
                )
                for connection in self._connections
                if connection.open
            ]
        for connection, events in wanted:
            if connection.answered and not events:
                self._drop(connection)
                continue
            if events == connection.watched:
                continue
            if not connection.watched:
                self._selector.register(connection.sock, events, connection)
            elif not events:
                self._selector.unregister(connection.sock)
            else:
                self._selector.modify(connection.sock, events, connection)
            connection.watched = events

    @staticmethod
    def _has_room(connection: _Connection) -> bool:
        """Whether more requests may be read: the inbox is not full and the client is reading its replies."""
        return len(connection.inbox) < _INBOX_LIMIT and len(connection.outbox) < _OUTBOX_LIMIT

    def _accept(self) -> None:
        try:
            sock, _ = self._listener.accept()
        except OSError:
            return
        sock.setblocking(False)
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_SNDBUF, _OUTBOX_LIMIT)
        with self._lock:
            self._connections.append(_Connection(sock))

    def _receive(self, connection: _Connection) -> None:
        try:
            data = connection.sock.recv(_RECEIVE_SIZE)
        except BlockingIOError:
            return
        except OSError:  # a reset: nothing more will be read or delivered
            self._drop(connection)
            return
        with self._lock:
            if data:
                connection.inbox += data
            else:  # the client finished sending; it may still read the replies to what it sent
                connection.ended = True

    def _send(self, connection: _Connection) -> None:
        with self._lock:
            pending = bytes(connection.outbox)
        try:
            sent = connection.sock.send(pending)
        except BlockingIOError:
            return
        except OSError:
            self._drop(connection)
            return
        with self._lock:
            del connection.outbox[:sent]

    def _drop(self, connection: _Connection) -> None:
        """Close a client that was reset or has had its replies; its unserviced bytes stay for one last ``service``."""
        if connection.watched:
            self._selector.unregister(connection.sock)
            connection.watched = 0
        connection.sock.close()
        with self._lock:
            connection.open = False
            if not connection.inbox:
                self._connections.remove(connection)
