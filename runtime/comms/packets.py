"""The host protocol of CM-4..CM-7: packet decoding and encoding, and the card's side of the exchange.

Write: ``EOT ID ID STX A1 A0 <data> ETX CHK``; read: ``EOT ID ID STX A1 A0 ENQ``; read reply:
``STX A1 A0 <data> ETX CHK``; ``CHK`` is the XOR of every byte after STX up to and including ETX.
The decoder is pure and byte-at-a-time, so the way a transport splits the stream never changes the result.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from decimal import Decimal
from enum import Enum, auto
from functools import reduce
from operator import xor
from typing import TypeAlias

from mintlang.records import record
from mintlang.runtime.comms.array import USER_ELEMENTS, CommsArray
from mintlang.runtime.errors import MintError
from mintlang.runtime.numbers import f32
from mintlang.runtime.printing import format_number

STX = 0x02
ETX = 0x03
EOT = 0x04
ENQ = 0x05
ACK = b"\x06"
NAK = b"\x15"
MAX_DATA = 60
"""Longest data field, in characters, in either direction."""

_NODE_CHARACTERS = b"0123456789ABCDEF"
_DIGITS = b"0123456789"
_NUMBER = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)")


@record
class WriteRequest:
    """A well-formed write with a correct checksum; ``values`` are already binary32."""

    node: int
    address: int
    values: tuple[float, ...]


@record
class ReadRequest:
    node: int
    address: int


@record
class BadPacket:
    """A packet the card must refuse; ``node`` is None when the ID is unreadable, so no card may answer it."""

    node: int | None
    reason: str


Request: TypeAlias = WriteRequest | ReadRequest | BadPacket


def checksum(payload: bytes) -> int:
    """The XOR of ``payload``: the address digits, the data and ETX."""
    return reduce(xor, payload, 0)


class _State(Enum):
    OUTSIDE = auto()
    ID = auto()
    ID_REPEAT = auto()
    START = auto()
    ADDRESS = auto()
    BODY = auto()
    CHECKSUM = auto()


class PacketDecoder:
    """Turns a byte stream into requests; bytes outside a packet are terminal traffic and are ignored.

    EOT starts a new packet and discards a partial one (CM-7 RC), except in the checksum position,
    where any byte is a legal checksum. A broken frame is refused as soon as the fault is seen and
    the rest of it is skipped until the next EOT; the data is judged once the checksum arrives.
    """

    __slots__ = ("_id", "_payload", "_state", "_sum")

    def __init__(self) -> None:
        self._state = _State.OUTSIDE
        self._id = 0
        self._payload = bytearray()
        self._sum = 0

    def feed(self, data: bytes) -> list[Request]:
        """Requests completed by ``data``, in arrival order; a partial packet waits for the next chunk."""
        requests = []
        for byte in data:
            request = self._step(byte)
            if request is not None:
                requests.append(request)
        return requests

    @property
    def _node(self) -> int:
        return _NODE_CHARACTERS.index(self._id)

    def _reject(self, node: int | None, reason: str) -> BadPacket:
        self._state = _State.OUTSIDE
        return BadPacket(node, reason)

    def _step(self, byte: int) -> Request | None:
        state = self._state
        if state is _State.CHECKSUM:
            self._state = _State.OUTSIDE
            return self._finish_write(byte)
        if byte == EOT:
            self._state = _State.ID
            self._payload.clear()
            self._sum = 0
            return None
        if state is _State.ID:
            if byte not in _NODE_CHARACTERS:
                return self._reject(None, "invalid node ID")
            self._id = byte
            self._state = _State.ID_REPEAT
        elif state is _State.ID_REPEAT:
            if byte != self._id:
                return self._reject(None, "node ID not repeated")
            self._state = _State.START
        elif state is _State.START:
            if byte != STX:
                return self._reject(self._node, "STX missing")
            self._state = _State.ADDRESS
        elif state is _State.ADDRESS:
            if byte not in _DIGITS:
                return self._reject(self._node, "address is not two decimal digits")
            self._payload.append(byte)
            self._sum ^= byte
            if len(self._payload) == 2:
                self._state = _State.BODY
        elif state is _State.BODY:
            return self._body_byte(byte)
        return None

    def _body_byte(self, byte: int) -> Request | None:
        if byte == ENQ:
            if len(self._payload) > 2:
                return self._reject(self._node, "read with data (or an address of more than two digits)")
            self._state = _State.OUTSIDE
            return ReadRequest(self._node, int(self._payload))
        self._sum ^= byte
        if byte == ETX:
            self._state = _State.CHECKSUM
        elif len(self._payload) <= 2 + MAX_DATA:
            # Kept only to one byte past the limit: enough to know the data is too long, and memory stays bounded.
            self._payload.append(byte)
        return None

    def _finish_write(self, received: int) -> Request:
        node = self._node
        if self._sum != received:
            return BadPacket(node, "wrong checksum")
        data = bytes(self._payload[2:])
        if len(data) > MAX_DATA:
            return BadPacket(node, f"data longer than {MAX_DATA} characters")
        values = _parse_values(data)
        if values is None:
            return BadPacket(node, "invalid data")
        return WriteRequest(node, int(self._payload[:2]), values)


def _parse_values(data: bytes) -> tuple[float, ...] | None:
    """Comma-separated plain decimals (no spaces, no exponent) that fit binary32, or None."""
    text = data.decode("ascii", errors="replace")
    fields = text.split(",")
    if not all(_NUMBER.fullmatch(field) for field in fields):
        return None
    try:
        return tuple(f32(float(field)) for field in fields)
    except MintError:
        return None


def _decimal(value: float) -> str:
    """Positional decimal text that reads back as ``value``: the protocol has no exponent notation."""
    text = format(Decimal(repr(float(value))), "f")
    return text.rstrip("0").rstrip(".") if "." in text else text


def _address_digits(address: int) -> bytes:
    if not 0 <= address <= 99:
        raise ValueError(f"comms address {address} does not fit two digits")
    return b"%02d" % address


def _header(node: int) -> bytes:
    if not 0 <= node < len(_NODE_CHARACTERS):
        raise ValueError(f"node {node} has no ID character (0-9 and A-F are nodes 0 to 15)")
    return bytes([EOT, _NODE_CHARACTERS[node], _NODE_CHARACTERS[node]])


def _framed(address: int, data: bytes) -> bytes:
    """``STX A1 A0 data ETX CHK``, the tail shared by host writes and card replies."""
    payload = _address_digits(address) + data + bytes([ETX])
    return bytes([STX]) + payload + bytes([checksum(payload)])


def encode_write(node: int, address: int, values: str | Sequence[float]) -> bytes:
    """A host write packet. A ``str`` is sent verbatim, so scripted hosts and tests can also send invalid data."""
    data = values if isinstance(values, str) else ",".join(_decimal(value) for value in values)
    if not data.isascii():  # the serial protocol carries bytes of ASCII text (CM-4)
        position, character = next((place, char) for place, char in enumerate(data) if not char.isascii())
        raise ValueError(f"the data must be ASCII text; {character!r} at position {position} is not")
    return _header(node) + _framed(address, data.encode("ascii"))


def encode_read(node: int, address: int) -> bytes:
    """A host read packet (it has no checksum)."""
    return _header(node) + bytes([STX]) + _address_digits(address) + bytes([ENQ])


def encode_reply(address: int, text: str) -> bytes:
    """The card's answer to a read."""
    return _framed(address, text.encode("ascii"))


class HostEndpoint:
    """The card's side of the protocol: applies requests for this node to the comms array and answers them.

    ``node`` is read per request, so a program changing ``NODE`` takes effect at once; a node
    above 15 has no ID character and hears nothing. Writes are external writes (EV-11).
    Call only from the simulation thread.
    """

    __slots__ = ("_array", "_decoder", "_node")

    def __init__(self, array: CommsArray, node: Callable[[], int]) -> None:
        self._array = array
        self._node = node
        self._decoder = PacketDecoder()

    def receive(self, data: bytes) -> bytes:
        """Feed one byte stream (e.g. scripted host traffic) through the endpoint's own decoder; return the replies."""
        return b"".join(self.answer(request) for request in self._decoder.feed(data))

    def answer(self, request: Request) -> bytes:
        """Apply one request; the reply is ACK/NAK for a write, data or NAK for a read, nothing for another node."""
        if request.node is None or request.node != self._node():
            return b""
        if isinstance(request, BadPacket):
            return NAK
        if isinstance(request, WriteRequest):
            return self._write(request)
        return self._read(request)

    def _write(self, request: WriteRequest) -> bytes:
        """All values or none (CM-7 RC): a write running past element 99 changes nothing."""
        last = request.address + len(request.values) - 1
        if request.address not in USER_ELEMENTS or last not in USER_ELEMENTS:
            return NAK
        for offset, value in enumerate(request.values):
            self._array.write(request.address + offset, value, external=True)
        return ACK

    def _read(self, request: ReadRequest) -> bytes:
        if request.address not in USER_ELEMENTS:
            return NAK
        return encode_reply(request.address, format_number(self._array.read(request.address)))
