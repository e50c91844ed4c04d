"""The comms array (CM-1): user elements 1..99, the system map 100..255, and #COMMS1..5 bookkeeping (EV-11)."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from mintlang.comms_map import SystemElement, system_element
from mintlang.runtime.comms.array import CommsArray
from mintlang.runtime.errors import MintError
from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.numbers import f32
from tests.runtime.running import simulate


class FakeController:
    """System data as the runtime would expose it: every mapped element reads 7, except OUT which holds writes."""

    def __init__(self) -> None:
        self.out = 0.0

    def read(self, address: int) -> float | None:
        element = system_element(address)
        if element is None:
            return None
        return self.out if element.keyword == "OUT" else 7.0

    def write(self, address: int, value: float) -> bool:
        element = system_element(address)
        if element is None or not element.writable:
            return False
        self.out = value
        return True


@pytest.fixture
def controller() -> FakeController:
    return FakeController()


@pytest.fixture
def comms(controller: FakeController) -> CommsArray:
    return CommsArray(controller.read, controller.write)


def error_code(call: Callable[[], object]) -> int:
    with pytest.raises(MintError) as raised:
        call()
    return raised.value.code


def keyword(address: int) -> str | None:
    element = system_element(address)
    return None if element is None else element.keyword


def test_user_elements_start_at_zero_and_hold_binary32(comms: CommsArray) -> None:
    assert [comms.read(i) for i in (1, 50, 99)] == [0.0, 0.0, 0.0]
    comms.write(15, 10.5, external=False)
    comms.write(16, 0.1, external=False)
    assert comms.read(15) == 10.5
    assert comms.read(16) == f32(0.1) != 0.1


def test_system_elements_are_read_through_the_runtime(comms: CommsArray) -> None:
    assert comms.read(130) == 7.0  # POS.2, the manual's example
    comms.write(222, 5, external=True)  # OUT is the one writable system element
    assert comms.read(222) == 5.0


def test_read_only_system_element_is_error_45(comms: CommsArray) -> None:
    assert error_code(lambda: comms.write(100, 1, external=False)) == 45
    assert error_code(lambda: comms.write(220, 1, external=True)) == 45


@pytest.mark.parametrize("address", [108, 221, 238, 255])
def test_reserved_element_is_error_46_for_reads_and_writes(comms: CommsArray, address: int) -> None:
    assert error_code(lambda: comms.read(address)) == 46
    assert error_code(lambda: comms.write(address, 1, external=False)) == 46


@pytest.mark.parametrize("address", [0, -1, 256, 1000])
def test_index_outside_1_to_255_is_error_2016(comms: CommsArray, address: int) -> None:
    assert error_code(lambda: comms.read(address)) == 2016
    assert error_code(lambda: comms.write(address, 1, external=False)) == 2016


def test_external_writes_to_elements_1_to_5_are_taken_once_sorted(comms: CommsArray) -> None:
    comms.write(5, 1, external=True)
    comms.write(2, 1, external=True)
    comms.write(2, 1, external=True)  # same value again still counts, once
    comms.write(6, 1, external=True)  # no event exists for element 6
    assert comms.take_external_writes() == (2, 5)
    assert comms.take_external_writes() == ()


def test_program_writes_never_raise_comms_events(comms: CommsArray) -> None:
    for address in range(1, 6):
        comms.write(address, 3, external=False)
    assert comms.take_external_writes() == ()


def test_system_map_axis_blocks() -> None:
    assert system_element(100) == SystemElement("POS", 0, writable=False)
    assert system_element(130) == SystemElement("POS", 2, writable=False)
    assert system_element(137) == SystemElement("FOLERROR", 2, writable=False)
    assert system_element(212) == SystemElement("FOLERROR", 7, writable=False)
    assert [keyword(115 + k) for k in range(8)] == [
        "POS",
        "VEL",
        "AXISMODE",
        "AXISERROR",
        "DAC",
        "ENCODER",
        "IDLE",
        "FOLERROR",
    ]
    assert all(system_element(100 + 15 * axis + k) is None for axis in range(8) for k in range(8, 15))


def test_system_map_io_and_misc_block() -> None:
    assert system_element(220) == SystemElement("IN", None, writable=False)
    assert system_element(222) == SystemElement("OUT", None, writable=True)
    assert [system_element(a) for a in (224, 231)] == [
        SystemElement("ADC", 0, writable=False),
        SystemElement("ADC", 7, writable=False),
    ]
    named = {a: keyword(a) for a in range(232, 240) if keyword(a)}
    assert named == {
        232: "ERR",
        233: "ERL",
        234: "ERRAXIS",
        235: "EXECUTION_STATUS",
        236: "BUFFER",
        237: "LINE",
        239: "FIRMWAREREVISION",
    }
    assert all(system_element(a) is None for a in (221, 223, 238, *range(240, 256)))


def test_only_100_to_255_belong_to_the_system_map() -> None:
    assert system_element(99) is None and system_element(256) is None
    assert sum(system_element(a) is not None for a in range(100, 256)) == 8 * 8 + 8 + 9


def test_a_program_reads_its_execution_status_buffer_and_line_from_the_misc_block() -> None:
    # CM-1: 235 running (2), 236 the file (1 program, 2 configuration), 237 the line, 239 the build number
    config = "RESETALL\nPRINT COMMS(235), COMMS(236), COMMS(237)\n"
    result = simulate("DIM x\nPRINT COMMS(235), COMMS(236), COMMS(237), COMMS(239)\n", config=config)
    assert result.terminal == "222\n2120\n"


def test_a_program_write_of_several_values_changes_nothing_when_one_element_refuses_it() -> None:
    # like a host write (CM-7 RC), all values or none: COMMS(100) is read-only
    result = simulate("COMMS(98) = 1, 2, 3\n")
    assert (result.stop.reason, result.err) == (StopReason.ERROR, 45)
    source = "COMMS(98) = 1, 2, 3\nEND\n#ONERROR\nPRINT COMMS(98), COMMS(99)\nRETURN\n"
    assert simulate(source).terminal == "00\n"
    assert simulate("COMMS(97) = 1, 2, 3\nPRINT COMMS(97), COMMS(98), COMMS(99)\n").terminal == "123\n"
