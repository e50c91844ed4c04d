"""The host port over a real TCP socket: the test plays the simulation thread, calling ``service`` every tick."""

from __future__ import annotations

import contextlib
import socket
import struct
import time
from collections.abc import Callable, Iterator

import pytest

from mintlang.runtime.comms.array import CommsArray
from mintlang.runtime.comms.packets import ACK, NAK, HostEndpoint, encode_read, encode_reply, encode_write
from mintlang.runtime.comms.server import HostPortServer

NODE = 2
TIMEOUT = 5.0
TICK = 0.001


class Card:
    """A comms array, its endpoint and the host port, driven tick by tick from the test."""

    def __init__(self, server: HostPortServer) -> None:
        self.comms = CommsArray(lambda address: None, lambda address, value: False)
        self.endpoint = HostEndpoint(self.comms, lambda: NODE)
        self.server = server

    def connect(self) -> socket.socket:
        client = socket.create_connection(("127.0.0.1", self.server.port), timeout=TIMEOUT)
        client.setblocking(False)
        return client

    def tick(self) -> None:
        self.server.service(self.endpoint)
        time.sleep(TICK)

    def exchange(self, client: socket.socket, data: bytes, reply_size: int) -> bytes:
        """Send ``data`` and run ticks until ``reply_size`` bytes have come back."""
        client.sendall(data)
        reply = b""
        deadline = time.monotonic() + TIMEOUT
        while len(reply) < reply_size and time.monotonic() < deadline:
            self.tick()
            with contextlib.suppress(BlockingIOError):
                reply += client.recv(4096)
        return reply

    def ticks_until(self, condition: Callable[[], bool]) -> bool:
        deadline = time.monotonic() + TIMEOUT
        while time.monotonic() < deadline:
            self.tick()
            if condition():
                return True
        return False


@pytest.fixture
def card() -> Iterator[Card]:
    with HostPortServer(0) as server:
        yield Card(server)


def test_server_binds_an_ephemeral_port_on_localhost(card: Card) -> None:
    assert card.server.port > 0


def test_a_host_session_of_good_and_bad_packets(card: Card) -> None:
    client = card.connect()
    assert card.exchange(client, encode_write(NODE, 1, "10,20.5"), 1) == ACK
    assert card.exchange(client, encode_read(NODE, 2), len(encode_reply(2, "20.5"))) == encode_reply(2, "20.5")
    bad_checksum = encode_write(NODE, 3, "7")[:-1] + b"\x00"
    assert card.exchange(client, bad_checksum, 1) == NAK
    assert card.exchange(client, encode_write(NODE, 3, "7,x"), 1) == NAK
    truncated = encode_write(NODE, 3, "99")[:7]  # EOT ID ID STX address and one data digit
    assert card.exchange(client, truncated + b"garbage" + encode_write(NODE, 3, "8"), 1) == ACK
    assert [card.comms.read(a) for a in (1, 2, 3)] == [10.0, 20.5, 8.0]
    assert card.comms.take_external_writes() == (1, 2, 3)
    client.close()


def test_bytes_take_effect_only_when_the_simulation_services_the_port(card: Card) -> None:
    client = card.connect()
    client.sendall(encode_write(NODE, 1, "5"))
    time.sleep(0.05)
    assert card.comms.read(1) == 0.0
    assert card.ticks_until(lambda: card.comms.read(1) == 5.0)
    client.close()


def test_each_connection_has_its_own_packet_state(card: Card) -> None:
    first, second = card.connect(), card.connect()
    packet = encode_write(NODE, 1, "1")
    first.sendall(packet[:4])
    assert card.exchange(second, encode_write(NODE, 2, "2"), 1) == ACK
    assert card.exchange(first, packet[4:], 1) == ACK
    assert (card.comms.read(1), card.comms.read(2)) == (1.0, 2.0)
    first.close()
    second.close()


def test_client_leaving_mid_packet_does_not_disturb_the_next_client(card: Card) -> None:
    leaver = card.connect()
    leaver.sendall(encode_write(NODE, 1, "1")[:5])
    for _ in range(20):
        card.tick()
    leaver.close()
    for _ in range(20):
        card.tick()
    client = card.connect()
    assert card.exchange(client, encode_write(NODE, 1, "9")[5:] + encode_write(NODE, 2, "2"), 1) == ACK
    assert (card.comms.read(1), card.comms.read(2)) == (0.0, 2.0)
    client.close()


def test_connection_reset_does_not_break_the_server(card: Card) -> None:
    rude = card.connect()
    rude.sendall(b"\x04\x32\x32\x02garbage")
    rude.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, struct.pack("ii", 1, 0))
    rude.close()  # linger 0: the peer sees a reset, not a clean close
    for _ in range(20):
        card.tick()
    client = card.connect()
    assert card.exchange(client, encode_read(NODE, 1), len(encode_reply(1, "0"))) == encode_reply(1, "0")
    client.close()


def test_a_packet_sent_just_before_closing_is_still_applied(card: Card) -> None:
    client = card.connect()
    client.sendall(encode_write(NODE, 4, "4"))
    client.close()
    assert card.ticks_until(lambda: card.comms.read(4) == 4.0)


def test_close_is_idempotent_and_refuses_new_clients() -> None:
    server = HostPortServer(0)
    port = server.port
    server.close()
    server.close()
    with pytest.raises(OSError):
        socket.create_connection(("127.0.0.1", port), timeout=TIMEOUT)
