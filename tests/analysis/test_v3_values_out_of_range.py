"""A constant written outside the range Mint v3's attributes table prints is "Out of range" (001:13136-13138),
v4's error 3, in ``mint check --dialect v3`` as in ``mint-run --dialect v3``.

The ranges are the v3 guide's chapter 10 rows: WAIT 2 to 65535 ms (001:12540), IMASK 0 to 255 (001:8884),
TERM 1 to 7 (001:12000), BAUD 300 to 19200 (001:6103), GAIN 0 to 255 (001:8302), TORQUE -100 to 100
(001:12109), BACKOFF 1 to 100 (001:6047), ACCELTIME 2 to 32000 (001:5690), HOME 0 to 6 (001:8677), OUT
0 to 255 (001:4344-4345) and OUT0 to OUT7 0 to 1 (001:10622). A setting printed without ".0" takes no
fraction (001:169): STOPMODE 1 or 2 (001:11908), ENABLE 0 or 1 (001:7558), ERRORIN 0, 1 or 2
(001:7863-7866), AXISCON's eight bits (001:6015); but SCALE rounds a fraction down (001:11610) before its
1 to 32000 holds it. A scaled row holds for the value in counts, the value times SCALE, which is at least 1
(001:11592): SPEED 0 to 5,300,000 (001:11785) refuses -5 whatever the scale, ACCEL 1000 to 8,388,607
(001:5635) refuses 0, but takes 10 at SCALE 100.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import run_source

OUTSIDE = [
    pytest.param("WAIT = 65536", "65536", id="001:12540 WAIT above 65535"),
    pytest.param("WT = 1", "1", id="001:12540 WAIT below 2, abbreviated"),
    pytest.param("IMASK = 256", "256", id="001:8884 IMASK"),
    pytest.param("TERM = 0", "0", id="001:12000 TERM"),
    pytest.param("BAUD = 100", "100", id="001:6103 BAUD"),
    pytest.param("GAIN = 300", "300", id="001:8302 GAIN"),
    pytest.param("TORQUE.1 = -101", "-101", id="001:12109 TORQUE"),
    pytest.param("BACKOFF = 0", "0", id="001:6047 BACKOFF"),
    pytest.param("ACCELTIME = 1", "1", id="001:5690 ACCELTIME"),
    pytest.param("SPEED[0,1] = 10, -5", "-5", id="001:11785 SPEED negative, the second value"),
    pytest.param("ACCEL = 0", "0", id="001:5635 ACCEL zero"),
    pytest.param("JOG = -6000000", "-6000000", id="001:9326 JOG past its far end at SCALE 1"),
    pytest.param("STOPMODE.1 = 0", "0", id="001:11908 STOPMODE below 1"),
    pytest.param("SM = 1.5", "1.5", id="001:11908 STOPMODE between its two settings"),
    pytest.param("AXISCON = 256", "256", id="001:6015 AXISCON past eight bits"),
    pytest.param("ENABLE = 2", "2", id="001:7558 ENABLE is 0 or 1"),
    pytest.param("ERRORIN = 3", "3", id="001:7863-7866 ERRORIN has three settings"),
    pytest.param("HOME.1 = 7", "7", id="001:8677 HOME above 6"),
    pytest.param("SCALE = 0", "0", id="001:11592 SCALE below 1"),
    pytest.param("SF = 0.5", "0.5", id="001:11610 SCALE rounds 0.5 down to 0"),
    pytest.param("TIME = 70000", "70000", id="001:12047 TIME above 65535"),
    pytest.param("OUT = 256", "256", id="001:4344-4345 OUT above 255"),
    pytest.param("OUT3 = 2", "2", id="001:10622 one output is 0 or 1"),
]


@pytest.mark.parametrize(("line", "value"), OUTSIDE)
def test_the_check_reports_what_the_run_stops_on(line: str, value: str) -> None:
    source = f"{line}\n"
    found = [(d.code, source[d.span.start : d.span.end]) for d in mintlang.check(source, dialect="v3")]
    assert found == [("E0003", value)]
    assert _stop_of(source) == (StopReason.ERROR, 1, True)


@pytest.mark.parametrize(
    "line",
    [
        *("WAIT = 2", "WAIT = 65535", "IMASK = 255", "TERM = 7", "BAUD = 9600", "GN = 255", "TORQUE = -100"),
        *("SPEED = 5", "STOPMODE = 2", "ENABLE = 0", "ERRORIN = 2", "HOME = 6", "OUT = 255", "OUT7 = 1"),
        "SCALE = 1.5",  # rounded down to 1 (001:11610)
        "TIME = 0",  # its own example (001:12060), where the table's range starts at 2 (001:12047)
    ],
)
def test_the_ends_of_each_range_are_no_error(line: str) -> None:
    assert mintlang.check(f"{line}\n", dialect="v3") == []


def test_a_scaled_value_a_scale_factor_can_bring_in_is_no_error() -> None:
    # ACCEL = 10 is 10 counts at SCALE 1, under 1000, but 1000 at SCALE 100: the check cannot know the scale
    source = "SCALE = 100\nACCEL = 10\n"
    assert mintlang.check(source, dialect="v3") == []
    assert _stop_of(source) == (StopReason.END, 2, False)  # the end, after its last line


def test_a_value_in_a_variable_is_left_to_the_run() -> None:
    source = "a = 300\nGAIN = a\n"
    assert mintlang.check(source, dialect="v3") == []
    assert _stop_of(source) == (StopReason.ERROR, 2, True)


def _stop_of(source: str) -> tuple[StopReason, int | None, bool]:
    """How the v3 run ended, on which line, and whether on "Out of range"."""
    stop = run_source(source, dialect="v3").stop
    return stop.reason, stop.line, "Out of range" in stop.message
