"""``VEL`` is the change of position over its sampling period, so at low speed it reads in steps of 500.

The guide: VEL is the change in position measured during the last sampling period, in user units per
second; quantization makes it inaccurate at low speeds, and the least value other than zero it can return
is 500 (000:17117-17123): one count in a 2 ms sample. IDLE needs |VEL| <= IDLEVEL (000:11744-11748).
"""

from __future__ import annotations

from tests.runtime.running import simulate

SAMPLES = 20


def _vel_samples(speed: int) -> list[str]:
    """VEL.0 read every 2 ms, 20 times, while axis 0 jogs at ``speed`` counts/s (reached within 2 ms)."""
    source = (
        "DIM i\nACCEL.0 = 500000 : DECEL.0 = 500000\n"
        f"JOG.0 = {speed}\nWAIT = 100\n"
        f"FOR i = 1 TO {SAMPLES}\n  PRINT VEL.0\n  WAIT = 2\nNEXT\n"
    )
    return simulate(source).terminal.split()


def test_at_250_counts_a_second_vel_reads_0_or_500() -> None:
    # one count every 4 ms: a 2 ms sample holds one count (500/s) or none (0), half the samples each
    samples = _vel_samples(250)
    assert len(samples) == SAMPLES
    assert set(samples) == {"0", "500"}
    assert samples.count("500") == SAMPLES // 2


def test_at_1000_counts_a_second_vel_reads_1000() -> None:
    # reached after 2 ms and 1 count, then one count a millisecond, on the millisecond: two in every 2 ms sample
    assert set(_vel_samples(1000)) == {"1000"}


def test_an_axis_is_idle_once_its_position_has_held_for_a_whole_sample() -> None:
    # the move starts at 2 ms and is at 1000 counts/s after 2 ms and 1 count: at tick t it is at t - 3 counts.
    # CANCEL at 100 ms holds the demand there (000:8009-8011); the count changed from 99 to 100 ms, so VEL
    # spans it at 101 (500) and reads 0 at 102: IDLE from 102
    source = (
        "SPEED.0 = 1000 : ACCEL.0 = 500000\nMOVER.0 = 5000 : GO.0\nWAIT = 100\nCANCEL.0\nPAUSE IDLE.0\nPRINT TIME\n"
    )
    assert simulate(source).terminal == "102\n"
