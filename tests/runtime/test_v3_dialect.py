"""The Mint v3 layer's parts one by one: numbers, trig, printing, messages, expectation names, controllers, the CLI.

The programs of ``tests/conformance/v3`` check the same rules end to end; these
tables pin each rule where it is made, with the v3 guide's line (001:LINE).
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from mintlang.dialect import Dialect
from mintlang.runtime.dialects.v3 import numbers, trig
from mintlang.runtime.dialects.v3.errors import V3Errors
from mintlang.runtime.dialects.v3.printing import format_binary, format_number
from mintlang.runtime.errors import MintError, NotSimulated
from mintlang.runtime.hardware import machine
from mintlang.runtime.motion.axis import ER_ABORT, ER_FOLLOWING
from mintlang.runtime.scenario.problems import Invalid
from mintlang.runtime.scenario.targets import Target, target
from tests.runtime.invoking import mint_run, write


@pytest.mark.parametrize(
    ("written", "held"),
    [
        pytest.param(1.002, 257 / 256, id="001:1161-1170 rounds to the nearest 256th"),
        pytest.param(0.15, 38 / 256, id="001:1171-1181"),
        pytest.param(-0.15, -38 / 256, id="negative"),
        pytest.param(1.5 / 256, 2 / 256, id="a half goes away from zero"),
        pytest.param(8_388_607.996, 8_388_607 + 255 / 256, id="the largest"),
    ],
)
def test_a_written_number_is_held_in_256ths(written: float, held: float) -> None:
    assert numbers.fixed(written) == held


@pytest.mark.parametrize(
    ("operator", "a", "b", "result"),
    [
        pytest.param("*", 38 / 256, 2, 76 / 256, id="0.15 * 2"),
        pytest.param("/", 1, 3, 85 / 256, id="1 / 3 drops the rest"),
        pytest.param("/", -1, 3, -85 / 256, id="toward zero"),
        pytest.param("MOD", -7, 3, -1, id="the dividend's sign"),
        pytest.param("&", 5, 6, 4, id="001:2021-2031"),
        pytest.param("|", 5, 2, 7, id="or"),
        pytest.param("AND", -1, 255, 255, id="two's complement"),
        pytest.param("<>", 1, 2, 1, id="a relation is 1"),
    ],
)
def test_operators_work_on_256ths(operator: str, a: float, b: float, result: float) -> None:
    assert numbers.BINARY_OPERATORS[operator](a, b) == result


@pytest.mark.parametrize(
    "undefined",
    [
        pytest.param(lambda: numbers.divide(1, 0), id="division by zero"),
        pytest.param(lambda: numbers.add(8_388_607, 1), id="past the largest"),
        pytest.param(lambda: numbers.fixed(1e9), id="a number too large"),
        pytest.param(lambda: numbers.toggle_byte(256), id="~ of more than a byte"),
        pytest.param(lambda: trig.sine(-1), id="an angle below 0"),
        pytest.param(lambda: format_binary(256), id="BINARY of more than a byte"),
    ],
)
def test_what_the_guide_leaves_undefined_is_not_simulated(undefined: Callable[[], object]) -> None:
    with pytest.raises(NotSimulated):
        undefined()


@pytest.mark.parametrize(
    ("function", "degrees", "value"),
    [
        pytest.param(trig.sine, 30, 500, id="001:2067"),
        pytest.param(trig.cosine, 30, 866, id="001:7051"),
        pytest.param(trig.sine, 245, -906, id="001:11775"),
        pytest.param(trig.tangent, 45, 1000, id="001:11979"),
        pytest.param(trig.tangent, 80, 5622, id="001:11981"),
        pytest.param(trig.tangent, 90, 8_000_000, id="001:11977"),
        pytest.param(trig.sine, 90, 1000, id="the top of the table"),
        pytest.param(trig.cosine, 180, -1000, id="cos 180"),
        pytest.param(trig.tangent, 135, -1000, id="tan in the second quadrant"),
    ],
)
def test_trig_returns_the_value_times_1000(function: Callable[[float], float], degrees: float, value: float) -> None:
    assert function(degrees) == value


@pytest.mark.parametrize(
    ("value", "printed"),
    [
        pytest.param(numbers.fixed(1.002), "1.003", id="001:1165-1167"),
        pytest.param(numbers.fixed(0.15), "0.148", id="001:1181"),
        pytest.param(numbers.fixed(-0.15), "-0.148", id="negative"),
        pytest.param(0.5, "0.5", id="trailing zeros dropped"),
        pytest.param(-1 / 256, "-0.003", id="the smallest negative"),
        pytest.param(-0.0, "0", id="never -0"),
        pytest.param(40000.0, "40000", id="whole"),
    ],
)
def test_print_shows_three_places_cut(value: float, printed: str) -> None:
    assert format_number(value) == printed


@pytest.mark.parametrize(
    ("value", "printed"), [(12, "00001100"), (7.9, "00000111"), (-1, "11111111"), (-0.5, "11111111")]
)
def test_binary_prints_a_byte(value: float, printed: str) -> None:
    assert format_binary(value) == printed


@pytest.mark.parametrize(
    ("error", "unit", "line", "message", "err"),
    [
        pytest.param(MintError(3, 2), "program", 10, "ERROR: Program: Out of range at line 10 on axis 2", 0),
        pytest.param(MintError(10, 1), "program", 4, "ERROR: Program: Motion in progress at line 4 on axis 1", 5),
        pytest.param(MintError(40, 0), "configuration", 3, "ERROR: Config: Servo off at line 3 on axis 0", 6),
        pytest.param(MintError(2016), "program", 9, "ERROR: Program: Invalid Index at line 9", None, id="untrappable"),
        pytest.param(MintError(12, 1), "program", 20, "ERROR: Program: Following Error at line 20 on axis 1", 11),
        pytest.param(MintError(12, 0), "program", 5, "ERROR: Program: Card Aborted at line 5 on axis 0", 13),
    ],
)
def test_errors_are_reported_as_v3_does(error: MintError, unit: str, line: int, message: str, err: int | None) -> None:
    style = V3Errors(lambda axis: ER_FOLLOWING | ER_ABORT if axis == 1 else ER_ABORT)
    assert style.message(error, unit, line, explained=False) == message
    assert style.number(error) == err


def test_an_error_v3_has_no_counterpart_of_is_not_simulated() -> None:
    with pytest.raises(NotSimulated):
        V3Errors(lambda axis: 0).number(MintError(2018))


@pytest.mark.parametrize(
    ("written", "canonical"),
    [
        ("GN.1", Target("GAIN.1", every_axis=False)),
        ("mode", Target("MODE", every_axis=True)),
        ("IN3", Target("IN3", every_axis=False)),
        ("IN.3", Target("IN.3", every_axis=False)),
        ("OUT.2", Target("OUT.2", every_axis=False)),
        ("count", Target("COUNT", every_axis=False, shown="count")),
    ],
)
def test_a_v3_program_expects_its_own_keywords(written: str, canonical: Target) -> None:
    assert target(written, Dialect.V3) == canonical


@pytest.mark.parametrize("written", ["OUT3", "TIME.0", "STOP"])
def test_a_v3_keyword_that_cannot_be_read_is_no_expectation(written: str) -> None:
    with pytest.raises(Invalid):
        target(written, Dialect.V3)


def test_each_generation_runs_on_its_own_controllers() -> None:
    assert machine(None, Dialect.V3).title == "EuroServo (ES/M3)"
    assert machine("smartmove-1", Dialect.V3).axis_count == 1
    assert machine(None, Dialect.V4).title == "NextMove PCI"
    with pytest.raises(ValueError, match="not a controller of the Mint v3 guide"):
        machine("nextmove-bx", Dialect.V3)
    with pytest.raises(ValueError, match="dialect v3"):
        machine("euroservo", Dialect.V4)


def test_mint_run_runs_a_v3_program(tmp_path: Path) -> None:
    program = write(tmp_path, "v3.mnt", "a = SIN 30\nPRINT a / 1000\n")
    result = mint_run("--dialect", "v3", program)
    assert (result.exit_code, result.stdout) == (0, "0.5\n")


def test_mint_run_runs_a_relation_written_with_a_blank_inside(tmp_path: Path) -> None:
    # 001:3096 PAUSE DEMAND > = 50: "> =" is ">="; a = 3 holds for >= 3 and <> 4 only
    source = (
        "a = 3\nIF a > = 3 THEN PRINT 1\nIF a < = 2 THEN PRINT 2\nIF a < > 3 THEN PRINT 3\nIF a < > 4 THEN PRINT 4\n"
    )
    result = mint_run("--dialect", "v3", write(tmp_path, "v3.mnt", source))
    assert (result.exit_code, result.stdout) == (0, "1\n4\n")


def test_mint_run_reads_peek_but_has_no_option_card_to_read(tmp_path: Path) -> None:
    # 001:10745: PEEK reads the option card's address space, hardware the simulator does not have
    result = mint_run("--dialect", "v3", write(tmp_path, "v3.mnt", "PRINT 1\nPRINT PEEK(10)\n"))
    assert (result.exit_code, result.stdout) == (1, "1\n")
    assert "PEEK (function) is not simulated" in result.output and "Syntax error" not in result.output


def test_a_v3_keyword_is_on_every_v3_controller(tmp_path: Path) -> None:
    # 001:5921: v3 reads and writes AUXDAC, which the v4 guide lists for fewer controllers than the simulated one;
    # v3 has no error 17 for it: its write is simply not simulated
    result = mint_run("--dialect", "v3", write(tmp_path, "v3.mnt", "PRINT 1\nAUXDAC = 1\n"))
    assert (result.exit_code, result.stdout) == (1, "1\n")
    assert "AUXDAC (write) is not simulated" in result.output and "error 17" not in result.output


@pytest.mark.parametrize("keyword", ["INCA", "INCR"])
def test_reading_a_keyword_v3_reads_is_no_programming_error(tmp_path: Path, keyword: str) -> None:
    # 001:9049, 9104: reading INCA or INCR tells whether the new end point was set up (v4's are write only);
    # the read is not simulated, and "Write only" would call the v3 program wrong
    result = mint_run("--dialect", "v3", write(tmp_path, "v3.mnt", f"PRINT 1\na = {keyword}.0\n"))
    assert (result.exit_code, result.stdout) == (1, "1\n")
    assert f"{keyword} (read) is not simulated" in result.output and "Write only" not in result.output


def test_a_move_on_amplifiers_never_enabled_says_how_v3_enables_them(tmp_path: Path) -> None:
    # 001:11409-11411: the amplifiers stay disabled from power-up until RESET or CONFIG; ENABLE = 1 also switches
    # them on (001:7547-7576). v3 has no DRIVEENABLE, the v4 hint's keyword.
    result = mint_run("--dialect", "v3", write(tmp_path, "v3.mnt", "MOVEA.0 = 10 : GO.0\n"))
    assert (result.exit_code, result.stdout) == (1, "ERROR: Program: Servo off at line 1 on axis 0\n")
    assert "until RESET, CONFIG or ENABLE = 1 enables them" in result.output and "DRIVEENABLE" not in result.output


def test_mint_run_refuses_a_v4_controller_for_a_v3_program(tmp_path: Path) -> None:
    program = write(tmp_path, "v3.mnt", "PRINT 1\n")
    result = mint_run("--dialect", "v3", "--controller", "nextmove-pci", program)
    assert result.exit_code == 2
    assert "not a controller of the Mint v3 guide" in result.output


def test_mint_run_goes_on_after_lasterr_with_no_error_to_display(tmp_path: Path) -> None:
    # 001:9632-9642: LASTERR displays the error that last ended a program; a run starts at power-up, so none has
    result = mint_run("--dialect", "v3", write(tmp_path, "v3.mnt", 'LASTERR\nPRINT "on"\n'))
    assert (result.exit_code, result.stdout) == (0, "on\n")
