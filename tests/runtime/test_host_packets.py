"""Host packets (CM-4..CM-7): what the card accepts, what it refuses, and what it answers."""

from __future__ import annotations

from itertools import pairwise

from hypothesis import given, settings
from hypothesis import strategies as st

from mintlang.runtime.comms.array import CommsArray
from mintlang.runtime.comms.packets import (
    ACK,
    ENQ,
    EOT,
    ETX,
    NAK,
    STX,
    BadPacket,
    HostEndpoint,
    PacketDecoder,
    ReadRequest,
    WriteRequest,
    checksum,
    encode_read,
    encode_reply,
    encode_write,
)
from mintlang.runtime.numbers import f32
from tests.fuzzing import examples

NODE = 2  # the power-up NODE (W-3)


def card(node: int = NODE) -> tuple[CommsArray, HostEndpoint]:
    comms = CommsArray(lambda address: None, lambda address, value: False)
    return comms, HostEndpoint(comms, lambda: node)


def user_elements(comms: CommsArray) -> list[float]:
    return [comms.read(address) for address in range(1, 100)]


# Packet layout


def test_write_packet_layout_and_checksum_over_address_data_and_etx() -> None:
    packet = encode_write(NODE, 12, "5")
    assert packet == bytes([EOT]) + b"22" + bytes([STX]) + b"125" + bytes([ETX, ord("1") ^ ord("2") ^ ord("5") ^ ETX])


def test_read_packet_layout_has_no_checksum() -> None:
    assert encode_read(0xB, 7) == bytes([EOT]) + b"BB" + bytes([STX]) + b"07" + bytes([ENQ])


def test_reply_layout() -> None:
    assert encode_reply(7, "12.5") == bytes([STX]) + b"0712.5" + bytes([ETX, checksum(b"0712.5\x03")])


def test_numbers_are_encoded_in_plain_decimal() -> None:
    assert encode_write(1, 10, [10, 0.00001, -23.4]) == encode_write(1, 10, "10,0.00001,-23.4")


def test_decoder_reports_typed_requests() -> None:
    decoder = PacketDecoder()
    stream = encode_write(NODE, 10, "10,20,30") + encode_read(NODE, 7) + encode_write(NODE, 10, "x")
    assert decoder.feed(stream) == [
        WriteRequest(NODE, 10, (10.0, 20.0, 30.0)),
        ReadRequest(NODE, 7),
        BadPacket(NODE, "invalid data"),
    ]


# Writes


def test_good_write_is_acknowledged_and_stored() -> None:
    comms, endpoint = card()
    assert endpoint.receive(encode_write(NODE, 12, "1234.5")) == ACK
    assert comms.read(12) == 1234.5


def test_values_are_stored_as_binary32() -> None:
    comms, endpoint = card()
    assert endpoint.receive(encode_write(NODE, 1, "0.1")) == ACK
    assert comms.read(1) == f32(0.1)


def test_multi_value_write_fills_consecutive_elements() -> None:
    comms, endpoint = card()
    assert endpoint.receive(encode_write(NODE, 10, "1234,45.6,-23.4")) == ACK
    assert [comms.read(a) for a in (10, 11, 12)] == [1234.0, f32(45.6), f32(-23.4)]


def test_write_running_past_99_is_refused_without_a_partial_write() -> None:
    comms, endpoint = card()
    assert endpoint.receive(encode_write(NODE, 98, "1,2,3")) == NAK
    assert comms.read(98) == comms.read(99) == 0.0
    assert endpoint.receive(encode_write(NODE, 98, "1,2")) == ACK
    assert comms.read(99) == 2.0


def test_address_00_is_refused() -> None:
    comms, endpoint = card()
    assert endpoint.receive(encode_write(NODE, 0, "1")) == NAK
    assert endpoint.receive(encode_write(NODE, 0, "")) == NAK  # the v3 abort packet
    assert endpoint.receive(encode_read(NODE, 0)) == NAK
    assert user_elements(comms) == [0.0] * 99


def test_wrong_checksum_is_refused() -> None:
    comms, endpoint = card()
    packet = encode_write(NODE, 12, "5")
    assert endpoint.receive(packet[:-1] + bytes([packet[-1] ^ 1])) == NAK
    assert comms.read(12) == 0.0


def test_invalid_data_is_refused() -> None:
    comms, endpoint = card()
    for data in ("", "1.2.3", "abc", "1,,2", ",1", " 1", "1 ", "1e3", "0x10", "+", ".", "1\x02"):
        assert endpoint.receive(encode_write(NODE, 12, data)) == NAK, data
    assert comms.read(12) == 0.0


def test_accepted_number_forms() -> None:
    comms, endpoint = card()
    assert endpoint.receive(encode_write(NODE, 1, "+1,-2,3.,.5,007")) == ACK
    assert [comms.read(a) for a in range(1, 6)] == [1.0, -2.0, 3.0, 0.5, 7.0]


def test_data_field_is_limited_to_60_characters() -> None:
    comms, endpoint = card()
    assert endpoint.receive(encode_write(NODE, 1, "1," * 29 + "10")) == ACK  # 60 characters
    assert endpoint.receive(encode_write(NODE, 1, "1," * 30 + "2")) == NAK  # 61 characters
    assert comms.read(31) == 0.0


def test_value_beyond_binary32_is_refused() -> None:
    comms, endpoint = card()
    assert endpoint.receive(encode_write(NODE, 1, "1" + "0" * 39)) == NAK
    assert comms.read(1) == 0.0


def test_every_host_write_to_elements_1_to_5_raises_a_comms_event() -> None:
    comms, endpoint = card()
    endpoint.receive(encode_write(NODE, 4, "1,2,3"))
    assert comms.take_external_writes() == (4, 5)
    endpoint.receive(encode_write(NODE, 4, "1"))  # unchanged value: still an event (EV-11 RC)
    assert comms.take_external_writes() == (4,)
    endpoint.receive(encode_write(NODE, 4, "1") + encode_write(NODE, 0, "2"))  # a refused write fires nothing
    assert comms.take_external_writes() == (4,)


# Reads


def test_good_read_answers_in_print_format() -> None:
    comms, endpoint = card()
    comms.write(7, 1.005103, external=False)
    comms.write(8, -27, external=False)
    assert endpoint.receive(encode_read(NODE, 7)) == encode_reply(7, "1.0051")
    assert endpoint.receive(encode_read(NODE, 8)) == encode_reply(8, "-27")
    assert comms.take_external_writes() == ()


def test_system_elements_cannot_be_reached_with_two_address_digits() -> None:
    _, endpoint = card()
    three_digits = bytes([EOT]) + b"22" + bytes([STX]) + b"130" + bytes([ENQ])
    assert endpoint.receive(three_digits) == NAK


def test_read_with_data_is_refused() -> None:
    _, endpoint = card()
    assert endpoint.receive(bytes([EOT]) + b"22" + bytes([STX]) + b"07" + b"1" + bytes([ENQ])) == NAK


# Addressing


def test_packets_for_other_nodes_are_ignored() -> None:
    comms, endpoint = card()
    assert endpoint.receive(encode_write(3, 12, "5") + encode_read(3, 12) + encode_write(3, 12, "bad")) == b""
    assert comms.read(12) == 0.0


def test_unreadable_node_id_gets_no_answer() -> None:
    comms, endpoint = card()
    packet = encode_write(NODE, 12, "5")
    assert endpoint.receive(packet[:2] + b"3" + packet[3:]) == b""  # "23": mismatched pair
    assert endpoint.receive(packet[:1] + b"aa" + packet[3:]) == b""  # lower case is not an ID
    assert comms.read(12) == 0.0


def test_node_ids_are_hex_digits_and_follow_node_changes() -> None:
    node = 2
    comms = CommsArray(lambda address: None, lambda address, value: False)
    endpoint = HostEndpoint(comms, lambda: node)
    node = 0xF
    assert encode_write(node, 1, "5")[1:3] == b"FF"
    assert endpoint.receive(encode_write(2, 1, "4")) == b""
    assert endpoint.receive(encode_write(0xF, 1, "5")) == ACK


def test_node_above_15_hears_nothing() -> None:
    _, endpoint = card(node=16)
    replies = b"".join(endpoint.receive(encode_write(n, 1, "5")) for n in range(16))
    assert replies == b""


# Framing and resynchronisation


def test_eot_discards_a_truncated_packet() -> None:
    comms, endpoint = card()
    truncated = encode_write(NODE, 12, "99")[:-3]
    assert endpoint.receive(truncated + encode_write(NODE, 13, "5")) == ACK
    assert (comms.read(12), comms.read(13)) == (0.0, 5.0)


def test_terminal_traffic_around_packets_is_ignored() -> None:
    _, endpoint = card()
    stream = b"PRINT POS\r\n" + encode_write(NODE, 12, "5") + b"\xff\x00junk\x03\x06" + encode_read(NODE, 12)
    assert endpoint.receive(stream) == ACK + encode_reply(12, "5")


def test_broken_frame_is_refused_and_skipped_until_the_next_eot() -> None:
    _, endpoint = card()
    no_stx = bytes([EOT]) + b"22" + b"12" + b"5" + bytes([ETX, 0])
    bad_digit = bytes([EOT]) + b"22" + bytes([STX]) + b"1x5" + bytes([ETX, 0])
    assert endpoint.receive(no_stx + bad_digit + encode_write(NODE, 1, "1")) == NAK + NAK + ACK


def test_checksum_byte_may_equal_eot() -> None:
    comms, endpoint = card()
    packet = encode_write(NODE, 1, "06")
    assert packet[-1] == EOT
    assert endpoint.receive(packet) == ACK
    assert comms.read(1) == 6.0


def test_packets_split_byte_by_byte_give_the_same_replies() -> None:
    stream = encode_write(NODE, 10, "10,20,30") + b"noise" + encode_read(NODE, 11) + encode_write(NODE, 1, "oops")
    _, whole = card()
    _, split = card()
    assert b"".join(split.receive(bytes([byte])) for byte in stream) == whole.receive(stream)
    assert whole.receive(b"") == b""


# Properties

# Random bytes rarely reach the deeper decoder states, so streams also mix in protocol fragments.
_FRAGMENTS = [
    *(bytes([byte]) for byte in (EOT, STX, ETX, ENQ)),
    *(b"\x0422\x02", b"12", b"9", b",", b".", b"-", b"x"),
    *(encode_write(NODE, 12, "1,2"), encode_write(NODE, 98, "1,2,3"), encode_read(NODE, 12)),
]
streams = st.lists(st.one_of(st.binary(max_size=4), st.sampled_from(_FRAGMENTS)), max_size=60).map(b"".join)


@settings(max_examples=examples(500))
@given(st.one_of(st.binary(max_size=200), streams))
def test_arbitrary_bytes_never_raise(stream: bytes) -> None:
    PacketDecoder().feed(stream)
    card()[1].receive(stream)


@settings(max_examples=examples(300))
@given(streams, st.lists(st.integers(min_value=0, max_value=120), max_size=6))
def test_chunking_never_changes_the_requests(stream: bytes, cuts: list[int]) -> None:
    bounds = [0, *sorted(cuts), len(stream)]
    chunked = PacketDecoder()
    requests = [request for start, end in pairwise(bounds) for request in chunked.feed(stream[start:end])]
    assert requests == PacketDecoder().feed(stream)


@settings(max_examples=examples(300))
@given(streams)
def test_eot_after_any_garbage_resynchronises(garbage: bytes) -> None:
    # One EOT may be taken as the checksum of a garbage packet; the second always starts afresh.
    requests = PacketDecoder().feed(garbage + bytes([EOT]) + encode_write(NODE, 12, "5"))
    assert requests[-1] == WriteRequest(NODE, 12, (5.0,))
