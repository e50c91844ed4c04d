"""A host that ends its sending side after its packets (a TCP half close, as ``nc -N`` or a script's
``shutdown`` does) is still listening, so the card answers every complete packet it sent: a write with
ACK or NAK (000:2503-2505), a read with ``STX A1 A0 <data> ETX CHK`` (000:2531-2548). Once the answers
are sent the card closes the connection, so the host's read ends instead of waiting.

The bytes are worked out by hand. Writing "7" to element 01 of node 2 is ``EOT '2' '2' STX '0' '1' '7'
ETX CHK`` with CHK = 0x30 ^ 0x31 ^ 0x37 ^ 0x03 = 0x35 (000:2474-2495); reading it back is
``EOT '2' '2' STX '0' '1' ENQ`` (000:2511-2526), answered ``STX '0' '1' '7' ETX 0x35``.
"""

from __future__ import annotations

import socket
import time
from collections.abc import Iterator

import pytest

from mintlang.runtime.comms.array import CommsArray
from mintlang.runtime.comms.packets import HostEndpoint
from mintlang.runtime.comms.server import HostPortServer

WRITE_7_TO_01 = b"\x0422\x02017\x03\x35"
READ_01 = b"\x0422\x0201\x05"
TIMEOUT = 5.0


@pytest.fixture
def server() -> Iterator[HostPortServer]:
    with HostPortServer(0) as port:
        yield port


def _send_then_half_close(server: HostPortServer, packets: bytes) -> tuple[bytes, bool]:
    """What the host receives, ticking the port as the simulation does; and whether the card then closed."""
    endpoint = HostEndpoint(CommsArray(lambda address: None, lambda address, value: False), lambda: 2)
    client = socket.create_connection(("127.0.0.1", server.port), timeout=TIMEOUT)
    client.sendall(packets)
    client.shutdown(socket.SHUT_WR)
    client.setblocking(False)
    received = b""
    deadline = time.monotonic() + TIMEOUT
    while time.monotonic() < deadline:
        server.service(endpoint)
        time.sleep(0.001)
        try:
            chunk = client.recv(4096)
        except BlockingIOError:
            continue
        if not chunk:
            client.close()
            return received, True
        received += chunk
    client.close()
    return received, False


@pytest.mark.parametrize(
    ("packets", "answer"),
    [
        pytest.param(WRITE_7_TO_01, b"\x06", id="write-acknowledged"),
        pytest.param(WRITE_7_TO_01 + READ_01, b"\x06" + b"\x02017\x03\x35", id="write-then-read"),
        pytest.param(WRITE_7_TO_01[:-1] + b"\x00", b"\x15", id="bad-checksum-refused"),
    ],
)
def test_the_answers_reach_the_host_and_then_the_card_closes(
    server: HostPortServer, packets: bytes, answer: bytes
) -> None:
    assert _send_then_half_close(server, packets) == (answer, True)


def test_a_half_packet_before_the_half_close_gets_no_answer_and_the_card_closes(server: HostPortServer) -> None:
    # A packet cut short is never answered (no ETX and checksum, 000:2503), and the card does not wait for the rest.
    assert _send_then_half_close(server, WRITE_7_TO_01[:6]) == (b"", True)
