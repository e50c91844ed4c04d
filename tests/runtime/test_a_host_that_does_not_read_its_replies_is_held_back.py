"""A host that sends reads and never reads the answers is held back, as flow control holds back a serial host:
the card stops taking its packets once its replies wait unsent, so the queue of replies stays bounded; when the
host reads again, it gets the answer to every packet it sent, in the order it sent them.

A read is ``EOT ID ID STX A1 A0 ENQ`` (000:2511-2526), answered ``STX A1 A0 <data> ETX CHK`` with CHK the XOR
of the bytes after STX up to and including ETX (000:2531-2548). The values are whole numbers below 2**24, which
a comms element holds exactly (000:717-718), so each answer's data is the number's digits.
"""

from __future__ import annotations

import contextlib
import itertools
import socket
import time
from collections.abc import Iterator
from functools import reduce
from operator import xor

import pytest

from mintlang.runtime.comms.array import CommsArray
from mintlang.runtime.comms.packets import HostEndpoint, Request
from mintlang.runtime.comms.server import HostPortServer

TIMEOUT = 20.0
TICK = 0.001
VALUES = {address: -8388600 - address for address in range(11, 20)}
"""Elements 11..19 hold -8388611 .. -8388619: each answer names its element twice, in its address and its value."""
HELD_BACK_TICKS = 200
"""Ticks in a row in which the host could send nothing: the card has stopped taking its packets."""
BOUND = 1 << 20
"""Answer bytes the card may queue for a host that reads nothing: its socket's buffer, the unsent replies and the
answers to one inbox are each some tens of KiB; without the hold-back, the flood goes on until ``FLOOD_LIMIT``."""
FLOOD_LIMIT = 2 * BOUND


def read_packet(address: int) -> bytes:
    return b"\x0422\x02" + b"%02d" % address + b"\x05"


PACKET = len(read_packet(11))


def answer(address: int) -> bytes:
    body = b"%02d" % address + str(VALUES[address]).encode() + b"\x03"
    return b"\x02" + body + bytes([reduce(xor, body)])


class CountingEndpoint(HostEndpoint):
    """The card's endpoint, counting the answer bytes it has produced."""

    __slots__ = ("answered",)

    def __init__(self, comms: CommsArray) -> None:
        super().__init__(comms, lambda: 2)
        self.answered = 0

    def answer(self, request: Request) -> bytes:
        reply = super().answer(request)
        self.answered += len(reply)
        return reply


@pytest.fixture
def server() -> Iterator[HostPortServer]:
    with HostPortServer(0) as port:
        yield port


@pytest.fixture
def endpoint() -> CountingEndpoint:
    comms = CommsArray(lambda address: None, lambda address, value: False)
    for address, value in VALUES.items():
        comms.write(address, value, external=False)
    return CountingEndpoint(comms)


def small_buffered_host(port: int) -> socket.socket:
    """A host with small socket buffers, like a serial port's, so that being held back shows after little traffic."""
    host = socket.socket()
    host.setsockopt(socket.SOL_SOCKET, socket.SO_SNDBUF, 4096)
    host.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
    host.connect(("127.0.0.1", port))
    host.setblocking(False)
    return host


def test_the_card_stops_taking_packets_then_answers_them_all_in_order(
    server: HostPortServer, endpoint: CountingEndpoint
) -> None:
    addresses = list(VALUES)
    stream = b"".join(read_packet(address) for address in addresses) * 64
    host = small_buffered_host(server.port)
    sent = blocked = 0
    while blocked < HELD_BACK_TICKS and endpoint.answered < FLOOD_LIMIT:
        try:
            accepted = host.send(stream[sent % len(stream) :])
        except BlockingIOError:
            blocked += 1
        else:
            sent, blocked = sent + accepted, 0
        server.service(endpoint)
        time.sleep(TICK)
    assert blocked == HELD_BACK_TICKS, f"the card took {sent} bytes from a host that read nothing"
    assert endpoint.answered <= BOUND

    start, tail = sent % len(stream), -sent % PACKET  # the last packet may have gone in part: the host completes it
    rest = (stream * 2)[start : start + tail]
    packets = (sent + tail) // PACKET
    expected = b"".join(answer(address) for address in itertools.islice(itertools.cycle(addresses), packets))
    received = bytearray()
    deadline = time.monotonic() + TIMEOUT
    while len(received) < len(expected) and time.monotonic() < deadline:
        with contextlib.suppress(BlockingIOError):
            rest = rest[host.send(rest) :] if rest else rest
        server.service(endpoint)
        time.sleep(TICK)
        with contextlib.suppress(BlockingIOError):
            while chunk := host.recv(1 << 16):
                received += chunk
    host.close()
    assert bytes(received) == expected
